// The example problems (examples/problems/*.toml) give the same sets as their
// C++ examples, bit for bit: the same network, built from the file.
#include <gtest/gtest.h>

#include "../../../examples/cpp/causal_chain_network.h"
#include "../../../examples/cpp/dead_reckoning_network.h"
#include "problem_text.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;

namespace {

SolveResult solve_file(const std::string& name) {
  const Problem p = load_problem(problem_test::problems_dir() + "/" + name);
  SolveResult r = solve_problem(p);
  EXPECT_FALSE(r.empty) << r.why_empty;
  return r;
}

// Same time points, same slices and gates, bit for bit.
void expect_identical(const TubeVector& a, const TubeVector& b) {
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.nb_slices(), b.nb_slices());
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) ASSERT_EQ(a.tdomain()->t(k), b.tdomain()->t(k)) << "time " << k;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t k = 0; k < a.nb_slices(); ++k) ASSERT_EQ(a[i].slice(k), b[i].slice(k)) << "component " << i << " slice " << k;
    for (std::size_t k = 0; k <= a.nb_slices(); ++k) ASSERT_EQ(a[i].gate(k), b[i].gate(k)) << "component " << i << " gate " << k;
  }
}

}  // namespace

// The C++ example's final box (kFinalBox) is made of the doubles nearest to
// 53.9, 55.9, ...; the file encloses those decimals rigorously (an ulp wider
// where they are not doubles). With the rigorous box in the C++ network, the
// sets are identical; with the example's own box, the file's sets contain it.
TEST(ProblemExamples, CausalChainIsTheCppNetwork) {
  const SolveResult r = solve_file("causal_chain.toml");
  const auto td = TDomain::create(0.0, causal_chain::kTf, 0.01);
  auto cpp = causal_chain::build(td, false);
  const auto decimal = [](const char* text) { return Function({"t"}, text).eval(IntervalVector{Interval(0)}); };
  cpp.x->set_gate(td->nb_slices(), IntervalVector{decimal("[53.9, 55.9]"), decimal("[6.9, 8.9]"), decimal("[-2.36, -2.32]")});
  const ContractStats s = cpp.cn->contract();
  ASSERT_FALSE(s.empty);
  expect_identical(*r.built.var("x").tubes, *cpp.x);
  expect_identical(*r.built.var("v").tubes, *cpp.v);
  EXPECT_EQ(r.schedule.back().stats.contractor_calls, s.contractor_calls);

  auto example = causal_chain::build(TDomain::create(0.0, causal_chain::kTf, 0.01), true);
  ASSERT_FALSE(example.cn->contract().empty);
  const TubeVector& x = *r.built.var("x").tubes;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t k = 0; k < x.nb_slices(); ++k) ASSERT_TRUE((*example.x)[i].slice(k).is_subset(x[i].slice(k)));
}

// The "cn" resolution of examples/cpp/dead_reckoning.cpp (solve_cn), at δ = 0.01.
TEST(ProblemExamples, DeadReckoningIsTheCppNetwork) {
  const SolveResult r = solve_file("dead_reckoning.toml");
  const auto td = TDomain::create(0.0, 64.0, 0.01);
  auto x = std::make_shared<TubeVector>(td, 4), v = std::make_shared<TubeVector>(td, 4);
  const Interval c = Interval(-1, 1) / Interval(100);
  x->set_gate(0, IntervalVector{Interval(-1, 1), Interval(-1, 1), Interval::half_pi() + c, c});
  (*v)[2] = Tube(td, "-9/20*cos(t/5) + [-0.001,0.001]");
  (*v)[3] = Tube(td, "1/10 + sin(t/4) + [-0.001,0.001]");
  ContractorNetwork cn;
  dead_reckoning::add_constraints(cn, x, v);
  ASSERT_FALSE(cn.contract().empty);
  expect_identical(*r.built.var("x").tubes, *x);
  expect_identical(*r.built.var("v").tubes, *v);
}

TEST(ProblemExamples, LineRangesEnclosesTheTruth) {
  const Problem p = load_problem(problem_test::problems_dir() + "/line_ranges.toml");
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  const Tube& x = (*r.built.var("x").tubes)[0];
  for (int i = 0; i <= 200; ++i) {
    const double t = i * 0.1;
    EXPECT_TRUE(x(t).contains(std::sin(t) + 1)) << "t = " << t;
  }
  // The ranges localise the robot: from [-10, 10] to a thin tube.
  EXPECT_LT(x.max_thickness(), 0.5);
}

TEST(ProblemExamples, InconsistentDataIsNoSolutionNamingTheConstraint) {
  std::string text = problem_test::read_file(problem_test::problems_dir() + "/line_ranges.toml");
  text.replace(text.find("value = \"[-10, 10]\""), 19, "value = \"[5, 10]\"");  // the robot is not there
  const SolveResult r = solve_problem(problem_test::parse(text));
  ASSERT_TRUE(r.empty);
  EXPECT_NE(r.why_empty.find("constraint"), std::string::npos) << r.why_empty;
  EXPECT_NE(r.why_empty.find("test.toml:"), std::string::npos) << r.why_empty;
}

TEST(ProblemExamples, AutoDeltaRefinesUntilStable) {
  const Problem p = load_problem(problem_test::problems_dir() + "/line_ranges.toml");
  SolveOptions o;
  o.auto_delta = true;
  o.tolerance = 0.05;
  const SolveResult r = solve_problem(p, o);
  ASSERT_FALSE(r.empty);
  ASSERT_GE(r.schedule.size(), 2u);
  for (std::size_t i = 1; i < r.schedule.size(); ++i) EXPECT_EQ(r.schedule[i].delta, r.schedule[i - 1].delta / 2);
  const auto& last = r.schedule.back();
  const auto& prev = r.schedule[r.schedule.size() - 2];
  EXPECT_TRUE(std::abs(prev.mean_thickness - last.mean_thickness) <= 0.05 * prev.mean_thickness ||
              r.schedule.size() >= 10);
}

// Constants (interval, box) and increments: the static beacons of thesis
// Table 2.1 as a file (one expr per range, solved once, no tube), and a
// tube from its increments.
TEST(ProblemExamples, StaticBeaconsWithConstantsOnly) {
  const std::string text = R"([time]
domain = [0, 1]
delta = 1
[var.x]
kind = "box"
dim = 2
[var.rho]
kind = "box"
dim = 3
value = ["[3.63, 4.43]", "[3.13, 3.93]", "[2.15, 2.95]"]
[[constraint]]
kind = "expr"
expr = "sqrt((x[0] + 0.5)^2 + (x[1] - 4)^2) - rho[0]"
[[constraint]]
kind = "expr"
expr = "sqrt((x[0] + 2.5)^2 + (x[1] + 2.5)^2) - rho[1]"
[[constraint]]
kind = "expr"
expr = "sqrt((x[0] - 2.5)^2 + (x[1] + 0.5)^2) - rho[2]"
)";
  const SolveResult r = solve_problem(problem_test::parse(text));
  ASSERT_FALSE(r.empty) << r.why_empty;
  const IntervalVector& x = *r.built.var("x").box;
  EXPECT_TRUE(x.contains(Vector{0.0, 0.0}));
  EXPECT_LT(x[0].diam(), 2.0);
  EXPECT_LT(x[1].diam(), 2.0);
}

TEST(ProblemExamples, IncrementsGiveTheGatesExactly) {
  const std::string text = R"([time]
domain = [0, 4]
delta = 1
[var.x]
kind = "tube"
at = [{ t = 0, value = 0 }]
[var.i]
kind = "tube"
value = "[1, 2]"
[[constraint]]
kind = "increment"
x = "x"
v = "i"
)";
  const SolveResult r = solve_problem(problem_test::parse(text));
  ASSERT_FALSE(r.empty);
  const Tube& x = (*r.built.var("x").tubes)[0];
  for (std::size_t k = 0; k <= 4; ++k) EXPECT_EQ(x.gate(k), Interval(double(k), 2.0 * k)) << k;
}
