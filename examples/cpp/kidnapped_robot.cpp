// Kidnapped robot (thesis 4.4.3): the dead-reckoning robot of 3.4,
//   x' = (x4 cos x3, x4 sin x3, u1, u2),
//   u1 ∈ -9/20 cos(t/5) + [-0.001, 0.001], u2 ∈ 1/10 + sin(t/4) + [-0.001, 0.001],
// on t ∈ [0, 64], with NO prior on the position (x1, x2) at any time but the
// single measurement (4.30) x1(37) ∈ [59.25, 61.25], x2(37) ∈ [36.16, 38.16].
//
// Heading and speed keep their initial box of (3.17), x3(0) ∈ π/2 ± 0.01,
// x4(0) ∈ ±0.01: the thesis only removes "a known initial condition" for the
// position and draws bounded tubes on [0, 64] (Fig. 4.11, 4.12); without any
// bound on x3, x4 the velocity, hence the position away from t = 37, would be
// unbounded (printed below as a check).
//
// Network: x' = v (CtcDeriv, forward AND backward from the measurement),
// v1 = x4 cos x3, v2 = x4 sin x3 (pointwise), v3 = u1, v4 = u2 (v3, v4 are
// the input tubes). The measurement is a gate: 37 is sampled in the TDomain
// before the tubes are built, then gate(37) := the box. The same network
// with CtcEval (t = [37, 37], z = the box) instead of the gate is run as a
// cross-check.
//
// Truth: RK4 from x0 = (0, 0, π/2, 0) with the nominal inputs; it passes at
// (60.2834, 37.0518) at t = 37, inside the measurement box. Also checked:
// the 16 extreme paths (corners of x3(0), x4(0) and constant input errors
// ±0.001) translated so that they pass at each corner of the measurement box
// at t = 37; with no prior on the position, a translation keeps a path
// feasible. Every path is sampled at the gates and 3 times inside each slice.
//
// The same problem by CtcIvp (validated Taylor integration, docs/ivp.md) at
// δ = 0.05: heading and speed (x3, x4, τ) alone, forward from x(0), give
// their box at t = 37 (the reachable set of two integrators of independent
// inputs is that box); then the whole state, its heading and speed tubes
// set to those, from gate 37 := the measurement × that box, forward to 64 and
// backward to 0. The same 65 paths are checked inside; one figure shows both
// tubes.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "dead_reckoning_ivp.h"
#include "example_args.h"
#include "example_check.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"

using namespace sillage;

namespace {

constexpr double kTf = 64.0, kTm = 37.0;
// (4.30), enclosing the decimal bounds (outward division).
const Interval kM1 = Interval(5925, 6125) / Interval(100), kM2 = Interval(3616, 3816) / Interval(100);

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

IntervalVector initial_box(bool heading_speed_known) {  // (3.17) without the position
  const Interval c = Interval(-1, 1) / Interval(100);
  if (!heading_speed_known) return IntervalVector(4);
  return {Interval(), Interval(), Interval::half_pi() + c, c};
}

struct Run {
  std::shared_ptr<TubeVector> x;
  ContractStats stats;
  double cpu = 0;
  std::size_t k37 = 0;
};

// td must have 37 as a time point (sampled before any tube is built on it:
// a network's layout is fixed).
Run solve(const std::shared_ptr<TDomain>& td, bool use_eval = false, bool heading_speed_known = true) {
  const double start = cpu_seconds();
  Run r;
  r.k37 = static_cast<std::size_t>(td->time_index(kTm));
  r.x = std::make_shared<TubeVector>(td, 4);
  auto v = std::make_shared<TubeVector>(td, 4);
  (*v)[2] = Tube(td, "-9/20*cos(t/5) + [-0.001, 0.001]");  // (3.16)
  (*v)[3] = Tube(td, "1/10 + sin(t/4) + [-0.001, 0.001]");
  r.x->set_gate(0, initial_box(heading_speed_known));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(Function({"x3", "x4", "v1"}, "x4*cos(x3) - v1")),
         {DomainRef::component(r.x, 2), DomainRef::component(r.x, 3), DomainRef::component(v, 0)});
  cn.add(std::make_shared<CtcFunction>(Function({"x3", "x4", "v2"}, "x4*sin(x3) - v2")),
         {DomainRef::component(r.x, 2), DomainRef::component(r.x, 3), DomainRef::component(v, 1)});
  cn.add(std::make_shared<CtcDeriv>(), {r.x, v});
  cn.set_name(r.x, "x");  // named, so that an empty network says which tube emptied
  cn.set_name(v, "v");
  if (use_eval) {
    auto t = std::make_shared<Interval>(kTm);
    auto z1 = std::make_shared<Interval>(kM1), z2 = std::make_shared<Interval>(kM2);
    cn.add(std::make_shared<CtcEval>(), {t, z1, DomainRef::component(r.x, 0), DomainRef::component(v, 0)});
    cn.add(std::make_shared<CtcEval>(), {t, z2, DomainRef::component(r.x, 1), DomainRef::component(v, 1)});
    cn.set_name(t, "t37");
    cn.set_name(z1, "z1");
    cn.set_name(z2, "z2");
  } else {
    (*r.x)[0].set_gate(r.k37, kM1);
    (*r.x)[1].set_gate(r.k37, kM2);
  }
  r.stats = cn.contract();
  r.cpu = cpu_seconds() - start;
  return r;
}

// CtcIvp on (x1, x2, x3, x4, tau) with the noise of (3.16) as the input
// (dead_reckoning_ivp.h): see the header comment. td has 37 as a time point.
Run solve_ivp(const std::shared_ptr<TDomain>& td) {
  const double start = cpu_seconds();
  Run r;
  r.k37 = static_cast<std::size_t>(td->time_index(kTm));
  const TubeVector noise(td, 2, dead_reckoning::ivp_noise());
  const IntervalVector b0 = initial_box(true);
  const CtcIvp heading(Function({"x3", "x4", "tau", "n1", "n2"}, "(-9/20*cos(tau/5) + n1, 1/10 + sin(tau/4) + n2, 1)"),
                       2, 10, TimePropag::FORWARD);
  TubeVector h(td, 3);
  h.set_gate(0, IntervalVector{b0[2], b0[3], Interval(0.0)});
  bool ok = heading.contract(h, noise);
  const IntervalVector h37 = h.gate(r.k37);
  const CtcIvp whole(dead_reckoning::ivp_contractor().function(), 2, 10, TimePropag::FWD_BWD);
  TubeVector x(td, 5);
  for (std::size_t i : {2, 3, 4}) x[i] = h[i - 2];  // heading and speed as known forward from x(0)
  x.set_gate(r.k37, IntervalVector{kM1, kM2, h37[0], h37[1], Interval(kTm)});
  ok = ok && whole.contract(x, noise);
  r.stats.empty = !ok;
  if (!ok) r.stats.emptiness = "CtcIvp: no trajectory of the inputs meets the measurement";
  r.x = std::make_shared<TubeVector>(x.subvector(0, 3));
  r.cpu = cpu_seconds() - start;
  return r;
}

using State = std::array<double, 4>;

// RK4 with step h from x0, inputs u* + (c1, c2); every step sampled.
std::vector<State> rk4(const State& x0, double c1, double c2, double h) {
  const auto f = [&](double t, const State& x) {
    return State{x[3] * std::cos(x[2]), x[3] * std::sin(x[2]), -9.0 / 20 * std::cos(t / 5) + c1,
                 0.1 + std::sin(t / 4) + c2};
  };
  const auto add = [](const State& a, const State& b, double s) {
    return State{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2], a[3] + s * b[3]};
  };
  const auto n = static_cast<std::size_t>(std::llround(kTf / h));
  std::vector<State> path{x0};
  State x = x0;
  for (std::size_t j = 0; j < n; ++j) {
    const double t = j * h;
    const State k1 = f(t, x), k2 = f(t + h / 2, add(x, k1, h / 2)), k3 = f(t + h / 2, add(x, k2, h / 2)),
                k4 = f(t + h, add(x, k3, h));
    for (int i = 0; i < 4; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    path.push_back(x);
  }
  return path;
}

double excess(const Interval& x, double v) {
  if (x.is_empty()) return INFINITY;
  return std::max({0.0, x.lb() - v, v - x.ub()});
}

// Largest distance of the path (sampled every h = δ/4) outside the tube:
// the value at time t must lie in every slice containing t, and in the gate
// when t is a time point (up to 1e-9: j*h and t_k may differ by an ulp).
double path_excess(const TubeVector& x, const std::vector<State>& path, double h) {
  const TDomain& td = *x.tdomain();
  double worst = 0;
  for (std::size_t j = 0; j < path.size(); ++j) {
    const double t = std::min(j * h, kTf);
    std::vector<std::size_t> gates, slices{td.slice_index(t)};
    for (std::size_t g : {slices[0], slices[0] + 1}) {
      if (g <= td.nb_slices() && std::abs(td.t(g) - t) < 1e-9) gates.push_back(g);
    }
    for (std::size_t g : gates) {
      if (g > 0) slices.push_back(g - 1);
      if (g < td.nb_slices()) slices.push_back(g);
    }
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t g : gates) worst = std::max(worst, excess(x[i].gate(g), path[j][i]));
      for (std::size_t k : slices) worst = std::max(worst, excess(x[i].slice(k), path[j][i]));
    }
  }
  return worst;
}

// The nominal path, then 16 extreme paths x 4 corners of the measurement box.
std::vector<std::vector<State>> reference_paths(double h) {
  const double pi2 = std::acos(0.0);
  std::vector<std::vector<State>> paths{rk4({0, 0, pi2, 0}, 0, 0, h)};
  const auto j37 = static_cast<std::size_t>(std::llround(kTm / h));
  for (int e = 0; e < 16; ++e) {
    const auto base = rk4({0, 0, pi2 + (e & 1 ? 0.01 : -0.01), e & 2 ? 0.01 : -0.01}, e & 4 ? 1e-3 : -1e-3,
                          e & 8 ? 1e-3 : -1e-3, h);
    for (int c = 0; c < 4; ++c) {
      const double p1 = c & 1 ? 61.25 : 59.25, p2 = c & 2 ? 38.16 : 36.16;
      auto p = base;
      const double d1 = p1 - base[j37][0], d2 = p2 - base[j37][1];
      for (State& s : p) s[0] += d1, s[1] += d2;
      paths.push_back(std::move(p));
    }
  }
  return paths;
}

double diagonal(const IntervalVector& b) { return std::hypot(b[0].diam(), b[1].diam()); }

// Component i of a path sampled every h, as a trajectory.
Trajectory component(const std::vector<State>& path, double h, std::size_t i) {
  std::vector<double> t, v;
  for (std::size_t j = 0; j < path.size(); ++j) t.push_back(std::min(j * h, kTf)), v.push_back(path[j][i]);
  return Trajectory(t, v);
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  bool ok = true;
  std::string summary;
  std::vector<std::pair<std::string, std::string>> figures;
  Run ri;  // CtcIvp at δ = 0.05
  for (const double dt : {0.05, 0.01, 0.005}) {
    const auto td = TDomain::create(0.0, kTf, dt);
    td->sample(kTm);
    const Run r = solve(td);
    const std::size_t N = r.x->nb_slices();
    const double h = dt / 4;
    const auto paths = reference_paths(h);
    const auto j37 = static_cast<std::size_t>(std::llround(kTm / h));
    if (dt == 0.05) {
      std::printf("nominal RK4 truth at t = 37: (%.4f, %.4f), %s the measurement box [59.25, 61.25] x [36.16, 38.16]\n",
                  paths[0][j37][0], paths[0][j37][1],
                  kM1.contains(paths[0][j37][0]) && kM2.contains(paths[0][j37][1]) ? "inside" : "NOT inside");
    }
    double worst_nominal = path_excess(*r.x, paths[0], h), worst = worst_nominal;
    for (std::size_t p = 1; p < paths.size(); ++p) worst = std::max(worst, path_excess(*r.x, paths[p], h));
    const bool inside = example::check_stats(r.stats) && example::enclosure_ok(*r.x) && worst <= 1e-9;
    ok = ok && inside;
    const IntervalVector p0 = r.x->gate(0).subvector(0, 1), p37 = r.x->gate(r.k37).subvector(0, 1),
                         pf = r.x->gate(N).subvector(0, 1);
    std::printf("delta = %-5g (%5zu slices): thickness d (box diagonal) at t = 0: %.3f, 37: %.3f, 64: %.3f; "
                "%zu iterations, %zu calls, %.4f s CPU\n",
                dt, N, diagonal(p0), diagonal(p37), diagonal(pf), r.stats.iterations, r.stats.contractor_calls, r.cpu);
    std::printf("  p(0) in [%.2f, %.2f] x [%.2f, %.2f], p(64) in [%.2f, %.2f] x [%.2f, %.2f]; truth inside: %s "
                "(max excess %.1e), 64 extreme paths inside: %s (max excess %.1e)\n",
                p0[0].lb(), p0[0].ub(), p0[1].lb(), p0[1].ub(), pf[0].lb(), pf[0].ub(), pf[1].lb(), pf[1].ub(),
                worst_nominal <= 1e-9 ? "yes" : "NO", worst_nominal, worst <= 1e-9 ? "yes" : "NO", worst);
    if (dt == 0.05) {
      ri = solve_ivp(td);
      double worst_ivp = 0;
      for (const auto& path : paths) worst_ivp = std::max(worst_ivp, path_excess(*ri.x, path, h));
      const bool ivp_inside = example::check_stats(ri.stats, "CtcIvp") && example::enclosure_ok(*ri.x) &&
                              worst_ivp <= 1e-9;
      ok = ok && ivp_inside;
      const IntervalVector q0 = ri.x->gate(0).subvector(0, 1), qf = ri.x->gate(N).subvector(0, 1);
      std::printf("  CtcIvp (%.3f s CPU): d(0) = %.3f, d(37) = %.3f, d(64) = %.3f; p(0) in [%.2f, %.2f] x [%.2f, %.2f], "
                  "p(64) in [%.2f, %.2f] x [%.2f, %.2f]; 65 paths inside: %s (max excess %.1e)\n",
                  ri.cpu, diagonal(q0), diagonal(ri.x->gate(ri.k37).subvector(0, 1)), diagonal(qf), q0[0].lb(),
                  q0[0].ub(), q0[1].lb(), q0[1].ub(), qf[0].lb(), qf[0].ub(), qf[1].lb(), qf[1].ub(),
                  ivp_inside ? "yes" : "NO", worst_ivp);
    }
    if (dt == 0.005) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "delta=0.005: d(0) = %.2f, d(37) = %.2f, d(64) = %.2f; %.0f ms", diagonal(p0),
                    diagonal(p37), diagonal(pf), 1000 * r.cpu);
      summary = buf;
      const Run e = solve(td, true);
      const bool same = *e.x == *r.x;
      std::printf("  with CtcEval(t = 37) instead of the gate: %s (%zu iterations, %.4f s CPU)\n",
                  same ? "the same tubes" : "different tubes", e.stats.iterations, e.cpu);
      ok = ok && (same || e.x->is_subset(*r.x) || r.x->is_subset(*e.x));
      const Run u = solve(td, false, false);
      std::printf("  without (3.17) on heading and speed either: x1(0) in %s, x1(64) in %s (unbounded, as expected)\n",
                  (*u.x)[0].gate(0).str().c_str(), (*u.x)[0].gate(N).str().c_str());

      const Trajectory t1 = component(paths[0], h, 0), t2 = component(paths[0], h, 1);
      Figure fig = tube_vector_figure(*r.x, 0, 1, "Kidnapped robot: [x1] x [x2], measurement at t = 37 (Fig. 4.11)",
                                      {}, &t1, &t2);
      fig.draw_box(IntervalVector{kM1, kM2}, Style{"#e53935", "#b71c1c", 1.0, 0.7, "measurement"});
      fig.save((out / "kidnapped_robot.svg").string());
      figures.emplace_back("kidnapped_robot.svg", "Kidnapped robot (4.30): [x1](.) x [x2](.), measurement box in "
                                                  "red, truth in red (Fig. 4.11)");
      Figure cmp = tube_vector_figure(*r.x, 0, 1,
                                      "Kidnapped robot: CtcDeriv network, delta = 0.005 (blue) vs CtcIvp, 0.05 (orange)",
                                      {}, &t1, &t2);
      TubeStyle orange;
      orange.slices = Style{"#f6c28b", "#c25e00", 0.4, 1.0, "slice"};
      draw_tube_vector_2d(cmp, *ri.x, 0, 1, orange, &t1, &t2);
      cmp.draw_box(IntervalVector{kM1, kM2}, Style{"#e53935", "#b71c1c", 1.0, 0.7, "measurement"});
      cmp.save((out / "kidnapped_robot_deriv_vs_ivp.svg").string());
      figures.emplace_back("kidnapped_robot_deriv_vs_ivp.svg",
                           "Kidnapped robot: the CtcDeriv network in blue, CtcIvp in orange, the measurement box");
      const IntervalVector qf = ri.x->gate(ri.x->nb_slices()).subvector(0, 1);
      std::snprintf(buf, sizeof buf, "; CtcIvp d(0) = %.2f, d(64) = %.2f", diagonal(ri.x->gate(0).subvector(0, 1)),
                    diagonal(qf));
      summary += buf;
      thickness_figure(r.x->subvector(0, 1), ThicknessMeasure::Diagonal,
                       "Kidnapped robot: thickness d(t) of [x1] x [x2] (Fig. 4.12)")
          .save((out / "kidnapped_robot_thickness.svg").string());
      figures.emplace_back("kidnapped_robot_thickness.svg",
                           "Kidnapped robot: diagonal thickness of [x1](.) x [x2](.) (Fig. 4.12)");
    }
  }
  example::print_result("kidnapped_robot", summary, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
