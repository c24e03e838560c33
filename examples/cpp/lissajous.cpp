// Higher-order differential constraints (thesis 4.4.2, CN (4.29)): a robot on
// the Lissajous curve x(t) = 5 (2 cos t, sin 2t), unknown to the solver, which
// only knows
//   1. ẍ1(t) ∈ -10 cos(t) + [-0.001, 0.001],
//   2. ẍ2 = -0.4 ẋ1 ẍ1,
//   3. ẋ(0) = (0, 10), x(0) ∈ [9.8, 10.2] × [-0.2, 0.2],
// on t ∈ [0, 2π] (one period of the curve). Tubes x, ẋ, ẍ (TubeVector)
// start at [-∞, ∞] except ẍ1, built from constraint 1 (slice k: the
// interval evaluation of -10 cos over the slice, plus the noise);
// CtcDeriv for x' = ẋ and ẋ' = ẍ, the pointwise CtcFunction of constraint 2
// on every slice and gate. The truth (analytic, with its derivatives) is
// checked inside all six tubes, rigorously.
//
// Nothing flows back to ẍ (CtcDeriv only contracts the primitive), so the
// network is a causal chain: ẍ1 -> ẋ1 -> (ẍ2) -> ẋ2 -> x2. Its pessimism on
// x2 is the slice-wise wrapping of constraint 2: [ẍ2](k) is as wide as
// 0.4 (|ẍ1| w(ẋ1(k)) + |ẋ1| w(ẍ1(k))) ≈ 80 δ, integrated twice; so δ matters.
//
// The same problem by CtcIvp (validated Taylor integration, docs/ivp.md):
// constraints 1-2 are the state equations of (x1, x2, ẋ1, ẋ2, τ) with the
// noise n ∈ [-0.001, 0.001] of ẍ1 as an input tube and τ' = 1 for the known
// part -10 cos τ; forward from the gate at 0. Both tubes in one figure.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "example_args.h"
#include "example_check.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/figures/tube_figure.h"

using namespace sillage;

namespace {

const double kTf = 2 * std::acos(-1.0);  // the double just below 2π: one period

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Run {
  std::shared_ptr<TubeVector> x, dx, ddx;
  ContractStats stats;
  double cpu = 0;
};

Run solve(double dt) {
  const double start = cpu_seconds();
  Run r;
  const auto td = TDomain::create(0.0, kTf, dt);
  r.x = std::make_shared<TubeVector>(td, 2);
  r.dx = std::make_shared<TubeVector>(td, 2);
  r.ddx = std::make_shared<TubeVector>(td, 2);
  (*r.ddx)[0] = Tube(td, "-10*cos(t) + [-0.001, 0.001]");  // constraint 1
  r.dx->set_gate(0, IntervalVector{Interval(0), Interval(10)});
  // [9.8, 10.2] x [-0.2, 0.2], enclosing the decimal bounds (outward division).
  r.x->set_gate(0, IntervalVector{Interval(98, 102) / Interval(10), Interval(-2, 2) / Interval(10)});
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(Function({"a2", "v1", "a1"}, "a2 + 0.4*v1*a1")),  // constraint 2
         {DomainRef::component(r.ddx, 1), DomainRef::component(r.dx, 0), DomainRef::component(r.ddx, 0)});
  cn.add(std::make_shared<CtcDeriv>(), {r.dx, r.ddx});
  cn.add(std::make_shared<CtcDeriv>(), {r.x, r.dx});
  cn.set_name(r.x, "x");  // named, so that an empty network says which tube emptied
  cn.set_name(r.dx, "dx");
  cn.set_name(r.ddx, "ddx");
  r.stats = cn.contract();
  r.cpu = cpu_seconds() - start;
  return r;
}

// CtcIvp on (x1, x2, v1, v2, tau), the noise of constraint 1 as the input:
// returns (x1, x2, v1, v2).
Run solve_ivp(double dt) {
  const double start = cpu_seconds();
  const auto td = TDomain::create(0.0, kTf, dt);
  const CtcIvp ctc(Function({"x1", "x2", "v1", "v2", "tau", "n"},
                            "(v1, v2, -10*cos(tau) + n, -0.4*v1*(-10*cos(tau) + n), 1)"),
                   1, 10, TimePropag::FORWARD);
  TubeVector x(td, 5);
  x.set_gate(0, IntervalVector{Interval(98, 102) / Interval(10), Interval(-2, 2) / Interval(10), Interval(0),
                               Interval(10), Interval(0)});
  Run r;
  r.stats.empty = !ctc.contract(x, TubeVector(td, 1, Interval(-1, 1) / Interval(1000)));
  if (r.stats.empty) r.stats.emptiness = "CtcIvp: no trajectory from x(0)";
  r.x = std::make_shared<TubeVector>(x.subvector(0, 1));
  r.dx = std::make_shared<TubeVector>(x.subvector(2, 3));
  r.cpu = cpu_seconds() - start;
  return r;
}

std::string box_str(const IntervalVector& b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "[%.4f, %.4f] x [%.4f, %.4f]", b[0].lb(), b[0].ub(), b[1].lb(), b[1].ub());
  return buf;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const Interval dom(0, kTf);
  // The truth and its derivatives (analytic: the check is rigorous).
  const std::vector<Trajectory> x_true{Trajectory("10*cos(t)", dom), Trajectory("5*sin(2*t)", dom)};
  const std::vector<Trajectory> dx_true{Trajectory("-10*sin(t)", dom), Trajectory("10*cos(2*t)", dom)};
  const std::vector<Trajectory> ddx_true{Trajectory("-10*cos(t)", dom), Trajectory("-20*sin(2*t)", dom)};

  bool ok = true;
  std::string summary;
  const double main_dt = 0.001;
  for (const double dt : {0.01, 0.001, 0.0001}) {
    const Run r = solve(dt);
    const std::size_t N = r.x->nb_slices();
    const bool inside = example::check_stats(r.stats) && example::enclosure_ok(*r.x) && example::enclosure_ok(*r.dx) &&
                        example::enclosure_ok(*r.ddx) && r.x->contains(x_true) && r.dx->contains(dx_true) &&
                        r.ddx->contains(ddx_true);
    ok = ok && inside;
    const double w1 = (*r.x)[0].max_thickness(), w2 = (*r.x)[1].max_thickness();
    std::printf("delta = %-6g (%6zu slices): x(2pi) in %s, max thickness x1 %.4f, x2 %.4f; %zu iterations, "
                "%zu calls, %.4f s CPU; truth inside x, x', x'': %s\n",
                dt, N, box_str(r.x->gate(N)).c_str(), w1, w2, r.stats.iterations, r.stats.contractor_calls, r.cpu,
                inside ? "yes" : "NO");
    if (dt == main_dt) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "delta=0.001: max thickness x1 %.3f, x2 %.3f; x(2pi) in %s; %.0f ms", w1, w2,
                    box_str(r.x->gate(N)).c_str(), 1000 * r.cpu);
      summary = buf;
      tube_vector_figure(*r.x, 0, 1, "Lissajous envelope [x1] x [x2], delta = 0.001 (Fig. 4.10)", {}, &x_true[0],
                         &x_true[1])
          .save((out / "lissajous.svg").string());
    }
  }
  // CtcIvp beside the network, on the same slices (the main delta).
  const Run ri = solve_ivp(main_dt), rd = solve(main_dt);
  const std::size_t N = ri.x->nb_slices();
  const bool ivp_inside = example::check_stats(ri.stats, "CtcIvp") && example::enclosure_ok(*ri.x) &&
                          example::enclosure_ok(*ri.dx) && ri.x->contains(x_true) && ri.dx->contains(dx_true);
  ok = ok && ivp_inside;
  const double wi1 = (*ri.x)[0].max_thickness(), wi2 = (*ri.x)[1].max_thickness();
  std::printf("CtcIvp, delta = %g: x(2pi) in %s, max thickness x1 %.4f, x2 %.4f; %.3f s CPU; truth inside x, x': %s\n",
              main_dt, box_str(ri.x->gate(N)).c_str(), wi1, wi2, ri.cpu, ivp_inside ? "yes" : "NO");
  char buf[200];
  std::snprintf(buf, sizeof buf, "; CtcIvp: max thickness x1 %.3f, x2 %.3f, x(2pi) in %s", wi1, wi2,
                box_str(ri.x->gate(N)).c_str());
  summary += buf;
  Figure cmp = tube_vector_figure(*rd.x, 0, 1, "Lissajous, delta = 0.001: CtcDeriv network (blue) vs CtcIvp (orange)",
                                  {}, &x_true[0], &x_true[1]);
  TubeStyle orange;
  orange.slices = Style{"#f6c28b", "#c25e00", 0.4, 1.0, "slice"};
  draw_tube_vector_2d(cmp, *ri.x, 0, 1, orange, &x_true[0], &x_true[1]);
  cmp.save((out / "lissajous_deriv_vs_ivp.svg").string());
  example::print_result("lissajous", summary, ok,
                        {{"lissajous.svg", "Lissajous robot, CN (4.29): envelope [x1](.) x [x2](.) on [0, 2pi] and "
                                           "the unknown truth (red), Fig. 4.10"},
                         {"lissajous_deriv_vs_ivp.svg",
                          "Lissajous robot: the CtcDeriv network in blue, CtcIvp in orange, the truth in red"}});
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
