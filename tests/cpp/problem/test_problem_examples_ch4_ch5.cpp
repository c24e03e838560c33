// The problem files of thesis 4.4.3 (kidnapped robot), 5.3.1 (low-cost
// beacons) and 5.3.2 (drifting clock) against the networks of their C++
// examples. The kidnapped robot is the same network bit for bit. The two
// others read their tables from CSV files, whose cells are enclosed to one
// ulp (their decimals as written): their sets contain the example's, an ulp
// away (the low-cost beacons also put their gates at the bounds of those
// ulp-wider times, so their slices differ by an ulp: compared on the gates
// both have).
#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <cmath>
#include <optional>

#include "../../../examples/cpp/dead_reckoning_network.h"
#include "../../../examples/cpp/drifting_clock_network.h"
#include "../../../examples/cpp/lowcost_beacons_network.h"
#include "problem_text.h"
#include "sillage/io/csv.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;

namespace {

SolveResult solve_file(const std::string& name, std::optional<double> delta = std::nullopt) {
  const Problem p = load_problem(problem_test::problems_dir() + "/" + name);
  SolveOptions o;
  o.delta = delta;
  SolveResult r = solve_problem(p, o);
  EXPECT_FALSE(r.empty) << r.why_empty;
  return r;
}

// The largest distance between the bounds of a and b (same TDomain times),
// and whether a is inside b everywhere.
struct Comparison {
  double distance = 0;
  bool inside = true;
};

void compare(const Interval& a, const Interval& b, Comparison& c) {
  c.inside = c.inside && a.is_subset(b);
  c.distance = std::max({c.distance, std::abs(a.lb() - b.lb()), std::abs(a.ub() - b.ub())});
}

Comparison compare_tubes(const Tube& a, const Tube& b) {
  Comparison c;
  EXPECT_EQ(a.nb_slices(), b.nb_slices());
  for (std::size_t k = 0; k < a.nb_slices(); ++k) compare(a.slice(k), b.slice(k), c);
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) compare(a.gate(k), b.gate(k), c);
  return c;
}

// The nominal path (examples/problems/data/robot_truth.csv, RK4 written with
// 6 decimals: 1e-6 is the margin) inside x at every truth time that is a gate.
void expect_path_inside(const TubeVector& x) {
  const CsvTable truth = CsvTable::read(problem_test::problems_dir() + "/data/robot_truth.csv");
  std::size_t checked = 0;
  for (std::size_t r = 0; r < truth.nb_rows(); ++r) {
    const std::span<const double> row = truth.row(r);
    const auto k = x.tdomain()->time_index(row[0]);
    if (k < 0) continue;
    for (std::size_t i = 0; i < 4; ++i)
      ASSERT_TRUE(x[i].gate(static_cast<std::size_t>(k)).inflate(1e-6).contains(row[i + 1])) << "x" << i << " at t = " << row[0];
    ++checked;
  }
  EXPECT_EQ(checked, truth.nb_rows());
}

}  // namespace

// The network of examples/cpp/kidnapped_robot.cpp (the gate at t = 37), at δ = 0.01.
TEST(ProblemExamples, KidnappedRobotIsTheCppNetwork) {
  const SolveResult r = solve_file("kidnapped_robot.toml");
  const auto td = TDomain::create(0.0, 64.0, 0.01);
  td->sample(37.0);
  auto x = std::make_shared<TubeVector>(td, 4), v = std::make_shared<TubeVector>(td, 4);
  (*v)[2] = Tube(td, "-9/20*cos(t/5) + [-0.001, 0.001]");
  (*v)[3] = Tube(td, "1/10 + sin(t/4) + [-0.001, 0.001]");
  const Interval c = Interval(-1, 1) / Interval(100);
  x->set_gate(0, IntervalVector{Interval(), Interval(), Interval::half_pi() + c, c});
  const auto k37 = static_cast<std::size_t>(td->time_index(37.0));
  (*x)[0].set_gate(k37, Interval(5925, 6125) / Interval(100));
  (*x)[1].set_gate(k37, Interval(3616, 3816) / Interval(100));
  ContractorNetwork cn;
  dead_reckoning::add_constraints(cn, x, v);  // the network of the kidnapped robot with its gates
  ASSERT_FALSE(cn.contract().empty);
  const TubeVector& fx = *r.built.var("x").tubes;
  ASSERT_EQ(fx.nb_slices(), x->nb_slices());
  for (std::size_t i = 0; i < 4; ++i) {
    const Comparison c = compare_tubes((*x)[i], fx[i]);
    EXPECT_TRUE(c.inside && c.distance == 0) << "component " << i << ": " << c.distance;
  }
  expect_path_inside(fx);
  // Bounded on [0, 64] from one measurement at t = 37, thinnest there.
  EXPECT_LT(fx[0].gate(k37).diam(), 2.0 + 1e-9);
  EXPECT_TRUE(std::isfinite(fx[0].gate(0).diam()) && fx[0].gate(0).diam() > fx[0].gate(k37).diam());
}

TEST(ProblemExamples, DriftingClockContainsTheCppSetsAnUlpAway) {
  const SolveResult r = solve_file("drifting_clock.toml");
  const auto td = TDomain::create(0.0, drifting_clock::kTf, 0.01);
  drifting_clock::Problem cpp = drifting_clock::build(td, 0.0);
  ASSERT_FALSE(cpp.cn->contract().empty);
  for (const auto& [name, tube] : {std::pair{"h", cpp.h}, std::pair{"y", cpp.y}, std::pair{"w", cpp.w}}) {
    const Comparison c = compare_tubes(*tube, (*r.built.var(name).tubes)[0]);
    EXPECT_TRUE(c.inside) << name;
    EXPECT_LT(c.distance, 1e-9) << name;
  }
  const TubeVector& x = *r.built.var("x").tubes;
  for (std::size_t i = 0; i < 2; ++i) {
    const Comparison c = compare_tubes((*cpp.x)[i], x[i]);
    EXPECT_TRUE(c.inside && c.distance < 1e-9) << "x" << i << " " << c.distance;
  }
  // The truth: the clock (5.23) and the boat, exactly (it lies on the edge of (5.25)).
  const Tube& h = (*r.built.var("h").tubes)[0];
  EXPECT_TRUE(h.contains(Trajectory(drifting_clock::kH, td->t0_tf())));
  EXPECT_TRUE(x.contains({Trajectory("90 + 100*cos(t)", td->t0_tf()), Trajectory("20 + 100*sin(t)", td->t0_tf())}));
  // The ranges correct the clock: [h] is thinner than with h(0) = 0 and h' in [phi] only.
  Tube h0(td), phi0(td, drifting_clock::kPhi);
  h0.set_gate(0, Interval(0.0));
  CtcDeriv().contract(h0, phi0);
  EXPECT_LT(h.max_thickness(), h0.max_thickness() / 2);
}

// At δ = 0.05 (the file's 0.01 takes seconds: the CLI test solves it).
TEST(ProblemExamples, LowcostBeaconsMatchTheCppSetsAnUlpAway) {
  const SolveResult r = solve_file("lowcost_beacons.toml", 0.05);
  lowcost_beacons::Problem cpp = lowcost_beacons::build(lowcost_beacons::make_tdomain(0.05), 0.0);
  ASSERT_FALSE(cpp.cn->contract().empty);
  const TubeVector& fx = *r.built.var("x").tubes;
  const TDomain &ft = *fx.tdomain(), &ct = *cpp.x->tdomain();
  Comparison c;
  std::size_t common = 0;
  for (std::size_t k = 0; k <= ct.nb_slices(); ++k) {
    const auto j = ft.time_index(ct.t(k));
    if (j < 0 || ft.t(static_cast<std::size_t>(j)) != ct.t(k)) continue;
    ++common;
    for (std::size_t i = 0; i < 4; ++i) compare((*cpp.x)[i].gate(k), fx[i].gate(static_cast<std::size_t>(j)), c);
  }
  EXPECT_GE(common, 1280u);
  EXPECT_LT(c.distance, 1e-6);
  expect_path_inside(fx);
  // Localised from an unknown start: the position within a few metres at t = 32.
  const auto k32 = static_cast<std::size_t>(ft.time_index(32.0));
  EXPECT_LT(fx[0].gate(k32).diam(), 10.0);
}
