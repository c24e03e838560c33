// CtcEvalList: the fixes of a tube as one network node. On the circle
// mission x(t) = (cos t, sin t), with range fixes to two beacons at uncertain
// times: the truth stays inside, the tube only shrinks, and the result is the
// network of one CtcEval node and one range node per fix to within the
// ratio's slack (the same contractors, run in another order); a wrong fix is
// an emptiness naming it; bad arguments are errors naming CtcEvalList.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "dynamics/circle_mission.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_eval_list.h"

using namespace sillage;

namespace {

// Ranges to the beacons (2, 0) and (-1, 3) every 0.37 s, the true range
// ± 0.02, stamped within ± 0.02 s of the true time; `wrong`: a fix 1 m long.
std::vector<TubeObservation> range_fixes(std::size_t wrong = SIZE_MAX) {
  const Function to_a({"a", "b"}, "sqrt((a - 2)^2 + b^2)"), to_b({"a", "b"}, "sqrt((a + 1)^2 + (b - 3)^2)");
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  std::vector<TubeObservation> obs;
  for (std::size_t i = 0; 0.2 + 0.37 * static_cast<double>(i) < 9.9; ++i) {
    const double t = 0.2 + 0.37 * static_cast<double>(i);
    const bool a = i % 2 == 0;
    const double r = a ? std::hypot(std::cos(t) - 2, std::sin(t)) : std::hypot(std::cos(t) + 1, std::sin(t) - 3);
    const Interval range = Interval(r + jitter(gen) + (i == wrong ? 1.0 : 0.0)).inflate(0.02);
    obs.push_back({Interval(t + jitter(gen)).inflate(0.02), IntervalVector(2),
                   std::make_shared<CtcFunction>(a ? to_a : to_b, range), "range " + std::to_string(i)});
  }
  return obs;
}

struct Solved {
  TubeVector x;
  ContractStats stats;
};

// The mission's network with the fixes as one CtcEvalList, or as a CtcEval
// node and a range node per fix.
Solved solve(const std::vector<TubeObservation>& obs, bool listed) {
  test::CircleMission m;
  auto x = std::make_shared<TubeVector>(m.x);
  auto v = std::make_shared<TubeVector>(m.v);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  if (listed) {
    cn.add(std::make_shared<CtcEvalList>(obs), {x, v});
  } else {
    const auto eval = std::make_shared<CtcEval>();
    for (const TubeObservation& o : obs) {
      auto z = std::make_shared<IntervalVector>(o.z);
      cn.add(eval, {std::make_shared<Interval>(o.t), z, x, v});
      cn.add(o.ctc, {z});
    }
  }
  const ContractStats s = cn.contract();
  return {*x, s};
}

double volume(const TubeVector& x) {
  double s = 0;
  for (std::size_t j = 0; j < x.size(); ++j)
    for (std::size_t k = 0; k <= x[j].nb_slices(); ++k) s += x[j].gate(k).diam();
  return s;
}

}  // namespace

TEST(CtcEvalList, KeepsTheTruthAndIsTheNetworkOfItsFixes) {
  const auto obs = range_fixes();
  const Solved list = solve(obs, true), rows = solve(obs, false);
  ASSERT_FALSE(list.stats.empty) << list.stats.emptiness;
  ASSERT_FALSE(rows.stats.empty) << rows.stats.emptiness;
  EXPECT_TRUE(test::holds_circle(list.x));
  EXPECT_TRUE(test::holds_circle(rows.x));
  // The ranges localise the unknown start: from a 20 m box to a thin tube.
  EXPECT_LT(list.x.max_thickness(), 0.5);
  std::printf("CtcEvalList: volume %.6f in %zu runs; a node per fix: %.6f in %zu runs\n", volume(list.x),
              list.stats.contractor_calls, volume(rows.x), rows.stats.contractor_calls);
  // The same contractors to a fixed point at the ratio 0.01: the same tube within that slack.
  EXPECT_NEAR(volume(list.x) / volume(rows.x), 1.0, 0.02);
  // Fewer runs: two nodes instead of 2 m + 1.
  EXPECT_LT(list.stats.contractor_calls, rows.stats.contractor_calls);
}

TEST(CtcEvalList, AtItsFixedPointAnotherContractChangesNothingAboveTheRatio) {
  test::CircleMission m;
  auto x = std::make_shared<TubeVector>(m.x);
  auto v = std::make_shared<TubeVector>(m.v);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.add(std::make_shared<CtcEvalList>(range_fixes()), {x, v});
  ASSERT_FALSE(cn.contract().empty);
  const TubeVector first = *x;
  const ContractStats again = cn.contract();
  ASSERT_FALSE(again.empty);
  EXPECT_TRUE(x->is_subset(first));
  EXPECT_NEAR(volume(*x) / volume(first), 1.0, 0.02);
  EXPECT_TRUE(test::holds_circle(*x));
}

TEST(CtcEvalList, AWrongFixIsAnEmptinessNamingIt) {
  const Solved s = solve(range_fixes(11), true);
  ASSERT_TRUE(s.stats.empty);
  EXPECT_EQ(s.stats.empty_contractor.rfind("CtcEvalList (range ", 0), 0u) << s.stats.emptiness;
  EXPECT_NE(s.stats.emptiness.find(" emptied "), std::string::npos) << s.stats.emptiness;
  EXPECT_TRUE(s.x.is_empty());
  // Unnamed fixes are named by their index.
  auto obs = range_fixes(11);
  for (auto& o : obs) o.name.clear();
  const Solved u = solve(obs, true);
  ASSERT_TRUE(u.stats.empty);
  EXPECT_EQ(u.stats.empty_contractor.rfind("CtcEvalList (fix ", 0), 0u) << u.stats.emptiness;
}

TEST(CtcEvalList, ScalarTubesAndPositionFixesWithoutContractor) {
  auto td = TDomain::create(0.0, 10.0, 0.1);
  auto x = std::make_shared<Tube>(td, Interval(-10, 10));
  auto v = std::make_shared<Tube>(td, Interval(0.9, 1.1));  // x' = 1 ± 0.1, x(t) = t - 5
  std::vector<TubeObservation> obs;
  for (double t : {1.0, 4.0, 8.0}) obs.push_back({Interval(t).inflate(0.05), IntervalVector{Interval(t - 5).inflate(0.1)}});
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.add(std::make_shared<CtcEvalList>(obs), {x, v});
  ASSERT_FALSE(cn.contract().empty);
  for (int k = 0; k <= 100; ++k) EXPECT_TRUE((*x)(k / 10.0).contains(k / 10.0 - 5)) << k;
  EXPECT_LT(x->gate(40).diam(), 0.5);
}

TEST(CtcEvalList, BadArgumentsNameIt) {
  EXPECT_THROW(CtcEvalList({}), Error);
  test::CircleMission m;
  auto x = std::make_shared<TubeVector>(m.x);
  auto v = std::make_shared<TubeVector>(m.v);
  ContractorNetwork cn;
  auto expect_error = [&](const std::vector<TubeObservation>& obs, const std::vector<DomainRef>& args,
                          const std::string& part) {
    try {
      cn.add(std::make_shared<CtcEvalList>(obs), args);
      ADD_FAILURE() << "no error for " << part;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  expect_error(range_fixes(), {DomainRef::component(x, 0)}, "ContractorNetwork::add(CtcEvalList): expects x and v");
  expect_error({{Interval(1), IntervalVector(3)}}, {x, v}, "observation 0 has 3 components, the tube 2");
  expect_error({{Interval(20, 30), IntervalVector(2)}}, {x, v}, "does not meet the time domain");
  EXPECT_EQ(cn.nb_ctc(), 0u);
}
