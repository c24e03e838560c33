// Dead reckoning of a mobile robot (thesis 3.4, (3.14)-(3.20)).
//
// State x = (x1, x2, psi, theta), x' = (x4 cos x3, x4 sin x3, u1, u2), inputs
// (3.16) known within 1/1000, x0 within the box (3.17), t in [0, 64]. Four
// resolutions, every one guaranteed (outward rounding included):
//  1. plain:  x3, x4 = primitives of [u]; v = x4 cos x3 by tube arithmetic;
//             x1, x2 = primitives of [v] (slice-wise, thesis (3.8));
//  2. cn:     CN (3.18) in a ContractorNetwork: x' = v by CtcDeriv (the
//             optimal slice rule of chapter 4, gates and polygons), the
//             pointwise v1 = x4 cos x3, v2 = x4 sin x3 on every slice and gate;
//  3. taylor: gates integrated with a first-order Taylor form per slice
//             (tube_taylor.h), ∫_slice v ∈ δ v(t_k) + δ²/2 [v'](k) from
//             either gate, v(t_k) from the GATES of x3, x4 and
//             [v'] = u2 cos x3 - x4 sin x3 u1 (the input noise is integrated
//             apart: it is not differentiable);
//  4. linear: beyond chapter 3, the correlation over time: x = nominal + e,
//             the first-order part of e(T) is a linear function of the
//             initial error and of the input noise, whose exact range is
//             0.01 (|A(0)| + |B(0)|) + 0.001 ∫ (|A| + |B|), with A, B the
//             adjoint integrals; the second-order remainder is bounded with
//             |e3|, |e4| <= 0.01 + 0.001 t. Computed at checkpoints, then
//             propagated by (3) in between and intersected with (3);
//  5. ivp:    CtcIvp (validated Taylor integration with Lohner's wrapping,
//             docs/ivp.md) on x' = f(x, u): the known part of the inputs
//             written in f with the time as a state (tau' = 1), the noise
//             n = u - u* as an input tube of width 2/1000 (a differential
//             inclusion: any n(t) in it).
// The nominal and extreme trajectories (RK4, fine step) are checked inside.
#include <algorithm>
#include <array>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "dead_reckoning_ivp.h"
#include "dead_reckoning_network.h"
#include "example_args.h"
#include "example_check.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/interval/elementary.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_ctc.h"
#include "sillage/tube/tube_integral.h"
#include "sillage/tube/tube_taylor.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;

namespace {

const Interval kNoise = Interval(-1, 1) / Interval(1000);  // (3.16), rigorous 1/1000

IntervalVector initial_box() {  // (3.17)
  const Interval c = Interval(-1, 1) / Interval(100);
  return {Interval(-1, 1), Interval(-1, 1), Interval::half_pi() + c, c};
}

// Process CPU time: the wall clock of a loaded machine says little.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Problem {
  std::shared_ptr<TDomain> td;
  Tube u1, u2;      // (3.16)
  Tube u1n, u2n;    // nominal inputs (no noise)
  Tube du1n, du2n;  // their derivatives
  explicit Problem(double dt)
      : td(TDomain::create(0.0, 64.0, dt)),
        u1(td, "-9/20*cos(t/5) + [-0.001,0.001]"),
        u2(td, "1/10 + sin(t/4) + [-0.001,0.001]"),
        u1n(td, "-9/20*cos(t/5)"),
        u2n(td, "1/10 + sin(t/4)"),
        du1n(td, "9/100*sin(t/5)"),
        du2n(td, "cos(t/4)/4") {}
};

// ---- 1. plain ----
TubeVector solve_plain(const Problem& p) {
  const IntervalVector x0 = initial_box();
  Tube x3 = primitive(p.u1, x0[2]), x4 = primitive(p.u2, x0[3]);
  Tube x1 = primitive(x4 * cos(x3), x0[0]), x2 = primitive(x4 * sin(x3), x0[1]);
  return TubeVector({x1, x2, x3, x4});
}

// ---- 2. the contractor network (3.18) ----
// x' = v (CtcDeriv, the differential contractor of chapter 4, optimal per
// slice), v1 = x4 cos x3, v2 = x4 sin x3 (pointwise), v3 = u1, v4 = u2,
// x(0) ∈ x0: one ContractorNetwork, propagated to its fixed point.
TubeVector solve_cn(const Problem& p) {
  auto x = std::make_shared<TubeVector>(p.td, 4), v = std::make_shared<TubeVector>(p.td, 4);
  x->set_gate(0, initial_box());
  (*v)[2] = p.u1;
  (*v)[3] = p.u2;
  ContractorNetwork cn;
  dead_reckoning::add_constraints(cn, x, v);
  example::check_stats(cn.contract(), "cn");  // empty: x is empty and fails enclosure_ok
  return *x;
}

// ---- 3. Taylor on the gates ----
struct TaylorSolution {
  TubeVector x;
  Tube v1, v2;
  std::vector<Interval> inc1, inc2;
};

TaylorSolution solve_taylor(const Problem& p) {
  const IntervalVector x0 = initial_box();
  Tube x3 = primitive_taylor(p.u1n, p.du1n, x0[2], kNoise);
  Tube x4 = primitive_taylor(p.u2n, p.du2n, x0[3], kNoise);
  const Tube c = cos(x3), s = sin(x3);
  Tube v1 = x4 * c, v2 = x4 * s;
  const Tube dv1 = p.u2 * c - x4 * s * p.u1, dv2 = p.u2 * s + x4 * c * p.u1;
  auto inc1 = taylor_increments(v1, dv1), inc2 = taylor_increments(v2, dv2);
  Tube x1 = primitive_from_increments(v1, inc1, x0[0]);
  Tube x2 = primitive_from_increments(v2, inc2, x0[1]);
  return {TubeVector({x1, x2, x3, x4}), std::move(v1), std::move(v2), std::move(inc1), std::move(inc2)};
}

// ---- 4. linearisation around the nominal, guaranteed remainder ----
// Nominal (real, exact): x3n = pi/2 - 9/4 sin(t/5), x4n = t/10 + 4 - 4 cos(t/4),
// so cos x3n = sin(9/4 sin(t/5)) =: a and sin x3n = cos(9/4 sin(t/5)) =: s.
// e3 = x3 - x3n = e30 + ∫ε1, e4 = e40 + ∫ε2, |e_0| <= 1/100, |ε| <= 1/1000.
//   x4 cos x3 = x4n a + a e4 - x4n s e3 + R1,
//   x4 sin x3 = x4n s + s e4 + x4n a e3 + R2,
//   |R| <= |x4n| E²/2 + E (E + E²/2), E(t) = 1/100 + t/1000 >= |e3|, |e4|
// (second-order Taylor of cos / sin around x3n). For ∫_0^T (α e4 + β e3):
//   = e40 A(0) + e30 B(0) + ∫_0^T (ε2 A + ε1 B),  A(s) = ∫_s^T α, B(s) = ∫_s^T β,
// whose range is ±[(|A(0)| + |B(0)|)/100 + ∫_0^T (|A| + |B|)/1000] (attained).

// Upper bound of that half-width at gate K; pa, pb: primitives of α, β.
double linear_radius(const Tube& pa, const Tube& pb, std::size_t K) {
  const TDomain& td = *pa.tdomain();
  const Interval aT = pa.gate(K), bT = pb.gate(K);
  Interval sum(0);
  for (std::size_t k = 0; k < K; ++k) {
    // A(s) over slice k lies in P(T) - [P](k); mag of an outward interval bounds |A| above.
    sum += td.slice_width(k) * (Interval((aT - pa.slice(k)).mag()) + Interval((bT - pb.slice(k)).mag()));
  }
  const Interval r = (Interval((aT - pa.gate(0)).mag()) + Interval((bT - pb.gate(0)).mag())) / Interval(100) +
                     sum / Interval(1000);
  return r.ub();
}

TubeVector solve_linear(const Problem& p, const TaylorSolution& ty, std::size_t nb_checkpoints) {
  const auto& td = p.td;
  const IntervalVector x0 = initial_box();
  const Tube a(td, "sin(9/4*sin(t/5))"), s(td, "cos(9/4*sin(t/5))"), x4n(td, "t/10 + 4 - 4*cos(t/4)");
  const Tube E(td, "1/100 + t/1000");
  const Tube da(td, "cos(9/4*sin(t/5))*9/20*cos(t/5)");   // (cos x3n)' = -sin(x3n) x3n'
  const Tube ds(td, "-sin(9/4*sin(t/5))*9/20*cos(t/5)");  // (sin x3n)' = cos(x3n) x3n'
  const Tube pa = primitive(a), ps = primitive(s);
  const Tube pb1 = primitive(-(x4n * s)), pb2 = primitive(x4n * a);
  const Tube rem = primitive(abs(x4n) * sqr(E) / Interval(2) + E * (E + sqr(E) / Interval(2)));
  const Tube v1n = x4n * a, v2n = x4n * s;
  const Tube n1 = primitive_taylor(v1n, p.u2n * a + x4n * da);
  const Tube n2 = primitive_taylor(v2n, p.u2n * s + x4n * ds);

  const std::size_t N = td->nb_slices();
  std::vector<Interval> g1(ty.x[0].gates().begin(), ty.x[0].gates().end());
  std::vector<Interval> g2(ty.x[1].gates().begin(), ty.x[1].gates().end());
  const std::size_t step = std::max<std::size_t>(1, N / nb_checkpoints);
  for (std::size_t K = step;; K = std::min(N, K + step)) {
    const double r = rem.gate(K).ub();
    g1[K] &= x0[0] + n1.gate(K) + Interval(-1, 1) * (Interval(linear_radius(pa, pb1, K)) + r);
    g2[K] &= x0[1] + n2.gate(K) + Interval(-1, 1) * (Interval(linear_radius(ps, pb2, K)) + r);
    if (K == N) break;
  }
  TubeVector x = ty.x;
  x[0] = primitive_from_increments(ty.v1, ty.inc1, x0[0], g1);
  x[1] = primitive_from_increments(ty.v2, ty.inc2, x0[1], g2);
  return x;
}

// ---- 5. validated integration (CtcIvp) ----
// f(x1, x2, x3, x4, tau, n1, n2) with the noise as inputs (dead_reckoning_ivp.h).
TubeVector solve_ivp(const Problem& p) {
  const CtcIvp ctc = dead_reckoning::ivp_contractor();
  TubeVector x(p.td, 5);
  x.set_gate(0, dead_reckoning::ivp_initial_gate());
  const TubeVector noise(p.td, 2, dead_reckoning::ivp_noise());
  if (!ctc.contract(x, noise)) std::printf("  ivp: EMPTY (no trajectory fits x0 and the inputs)\n");
  return x.subvector(0, 3);
}

// ---- checks: RK4 trajectories (fine step δ/4) sampled at the gates and inside slices ----
struct Check {
  std::size_t misses = 0, borderline = 0;  // excess > 1e-9, excess in (0, 1e-9]
  double max_excess = 0;
};

double excess(const Interval& x, double v) {
  if (x.is_empty()) return INFINITY;
  return std::max({0.0, x.lb() - v, v - x.ub()});
}

struct Path {
  std::vector<double> t;
  std::vector<std::array<double, 4>> x;
};

Path rk4(const std::array<double, 4>& x0, double c1, double c2, double h, double tf) {
  auto f = [&](double t, const std::array<double, 4>& x) {
    return std::array<double, 4>{x[3] * std::cos(x[2]), x[3] * std::sin(x[2]), -9.0 / 20 * std::cos(t / 5) + c1,
                                 0.1 + std::sin(t / 4) + c2};
  };
  Path p;
  const std::size_t n = static_cast<std::size_t>(std::llround(tf / h));
  std::array<double, 4> x = x0;
  p.t.push_back(0), p.x.push_back(x);
  for (std::size_t j = 0; j < n; ++j) {
    const double t = j * h;
    auto add = [](const std::array<double, 4>& a, const std::array<double, 4>& b, double s) {
      return std::array<double, 4>{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2], a[3] + s * b[3]};
    };
    const auto k1 = f(t, x), k2 = f(t + h / 2, add(x, k1, h / 2)), k3 = f(t + h / 2, add(x, k2, h / 2)),
               k4 = f(t + h, add(x, k3, h));
    for (int i = 0; i < 4; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    p.t.push_back((j + 1) * h), p.x.push_back(x);
  }
  return p;
}

// Paths computed with h = δ/4: sample j*h is gate j/4 when j % 4 == 0, else inside slice j/4.
void check(const TubeVector& x, const Path& path, Check& c) {
  for (std::size_t j = 0; j < path.t.size(); ++j) {
    const std::size_t k = j / 4;
    for (std::size_t i = 0; i < 4; ++i) {
      double e = 0;
      if (j % 4 == 0) {
        e = excess(x[i].gate(k), path.x[j][i]);
        if (k > 0) e = std::max(e, excess(x[i].slice(k - 1), path.x[j][i]));
        if (k < x.nb_slices()) e = std::max(e, excess(x[i].slice(k), path.x[j][i]));
      } else {
        e = excess(x[i].slice(k), path.x[j][i]);
      }
      if (e > 1e-9) ++c.misses;
      else if (e > 0) ++c.borderline;
      c.max_excess = std::max(c.max_excess, e);
    }
  }
}

std::vector<Path> reference_paths(double dt) {
  std::vector<Path> paths;
  const double h = dt / 4, pi2 = std::acos(0.0);
  paths.push_back(rk4({0, 0, pi2, 0}, 0, 0, h, 64));  // nominal first
  for (int e = 0; e < 16; ++e) {                      // corners of x0 (3, 4) x input errors
    const double s3 = e & 1 ? 1 : -1, s4 = e & 2 ? 1 : -1, c1 = e & 4 ? 1e-3 : -1e-3, c2 = e & 8 ? 1e-3 : -1e-3;
    paths.push_back(rk4({e & 1 ? 1.0 : -1.0, e & 2 ? -1.0 : 1.0, pi2 + 0.01 * s3, 0.01 * s4}, c1, c2, h, 64));
  }
  return paths;
}

std::string box_str(const Interval& a, const Interval& b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "[%.2f, %.2f] x [%.2f, %.2f]", a.lb(), a.ub(), b.lb(), b.ub());
  return buf;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  bool all_inside = true;
  std::string summary;
  std::vector<std::pair<std::string, std::string>> figures;
  for (double dt : {0.05, 0.01, 0.005, 0.001}) {
    Problem p(dt);
    const std::size_t N = p.td->nb_slices();
    std::vector<std::pair<std::string, TubeVector>> results;
    std::vector<double> times;
    auto run = [&](const char* name, const std::function<TubeVector()>& solve) {
      const double t0 = cpu_seconds();
      results.emplace_back(name, solve());
      times.push_back(cpu_seconds() - t0);
    };
    const double t_start = cpu_seconds();
    run("plain", [&] { return solve_plain(p); });
    run("cn", [&] { return solve_cn(p); });
    TaylorSolution ty{TubeVector(p.td, 4), Tube(p.td), Tube(p.td), {}, {}};
    run("taylor", [&] {
      ty = solve_taylor(p);
      return ty.x;
    });
    run("linear", [&] { return solve_linear(p, ty, 64); });
    // CtcIvp never steps across a gate: 64000 slices cost ~19 s CPU for the
    // same box as 12800 (the demo stays under 30 s); δ = 0.001 shows the others.
    if (dt >= 0.005) run("ivp", [&] { return solve_ivp(p); });
    const double t_total = cpu_seconds() - t_start;

    const std::vector<Path> paths = reference_paths(dt);
    std::printf("delta = %g (%zu slices), all %zu resolutions %.3f s CPU\n", dt, N, results.size(), t_total);
    for (std::size_t m = 0; m < results.size(); ++m) {
      const TubeVector& x = results[m].second;
      Check c;
      for (const Path& path : paths) check(x, path, c);
      all_inside = all_inside && example::enclosure_ok(x) && c.misses == 0;
      std::printf("  %-7s p(tf) in %s  (%.3f s CPU)  max thickness %.3f; 17 RK4 paths: %zu misses, %zu borderline, "
                  "max excess %.1e\n",
                  results[m].first.c_str(), box_str(x[0].gate(N), x[1].gate(N)).c_str(), times[m],
                  x.subvector(0, 1).max_thickness(), c.misses, c.borderline, c.max_excess);
    }
    const Path& nom = paths.front();
    std::printf("  nominal RK4 p(tf) = (%.4f, %.4f)\n", nom.x.back()[0], nom.x.back()[1]);
    // The hull of the sampled final positions: an inner bound of the true set.
    Interval h1 = Interval::empty(), h2 = Interval::empty();
    for (const Path& path : paths) h1 |= Interval(path.x.back()[0]), h2 |= Interval(path.x.back()[1]);
    std::printf("  hull of the 17 RK4 p(tf): %s; CtcDeriv (cn) %s, CtcIvp %s\n", box_str(h1, h2).c_str(),
                box_str(results[1].second[0].gate(N), results[1].second[1].gate(N)).c_str(),
                results.size() > 4 ? box_str(results[4].second[0].gate(N), results[4].second[1].gate(N)).c_str()
                                   : "not run");
    if (dt == 0.005) {
      summary = "delta=0.005: p(64) in " + box_str(results[0].second[0].gate(N), results[0].second[1].gate(N)) +
                " (plain), " + box_str(results[1].second[0].gate(N), results[1].second[1].gate(N)) + " (cn), " +
                box_str(results[2].second[0].gate(N), results[2].second[1].gate(N)) + " (taylor), " +
                box_str(results[3].second[0].gate(N), results[3].second[1].gate(N)) + " (linear), " +
                box_str(results[4].second[0].gate(N), results[4].second[1].gate(N)) + " (ivp)";
      std::vector<double> ts, x1, x2;
      for (std::size_t j = 0; j < nom.t.size(); j += 4) ts.push_back(nom.t[j]), x1.push_back(nom.x[j][0]),
                                                        x2.push_back(nom.x[j][1]);
      const Trajectory tr1(ts, x1), tr2(ts, x2);
      const char* names[] = {"plain", "cn", "taylor", "linear", "ivp"};
      for (std::size_t m : {std::size_t(0), std::size_t(3), std::size_t(4)}) {
        const std::string f = std::string("dead_reckoning_") + names[m] + ".svg";
        tube_vector_figure(results[m].second, 0, 1,
                           std::string("[x1] x [x2], ") + names[m] + ", delta = 0.005", {}, &tr1, &tr2)
            .save((out / f).string());
        figures.emplace_back(f, std::string("Dead reckoning (3.18): [x1](.) x [x2](.), ") + names[m] +
                                    " resolution, nominal path in red");
        const std::string g = std::string("dead_reckoning_thickness_") + names[m] + ".svg";
        thickness_figure(results[m].second.subvector(0, 1), ThicknessMeasure::Diagonal,
                         std::string("Thickness of [x1] x [x2], ") + names[m])
            .save((out / g).string());
        figures.emplace_back(g, std::string("Thickness d(t) of [x1](.) x [x2](.), ") + names[m]);
      }
      // CtcDeriv (cn, blue) and CtcIvp (orange, drawn over it) in one figure.
      Figure cmp = tube_vector_figure(results[1].second, 0, 1, "[x1] x [x2]: CtcDeriv (blue) vs CtcIvp (orange)",
                                      {}, &tr1, &tr2);
      TubeStyle orange;
      orange.slices = Style{"#f6c28b", "#c25e00", 0.4, 1.0, "slice"};
      draw_tube_vector_2d(cmp, results[4].second, 0, 1, orange, &tr1, &tr2);
      cmp.save((out / "dead_reckoning_deriv_vs_ivp.svg").string());
      figures.emplace_back("dead_reckoning_deriv_vs_ivp.svg",
                           "Dead reckoning, delta = 0.005: CtcDeriv network (3.18) in blue, CtcIvp in orange, "
                           "nominal path in red");
    }
  }
  example::print_result("dead_reckoning", summary, all_inside, figures);
  return all_inside ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
