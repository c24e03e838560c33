// CtcT1T2 (Alg. 11, (7.23)-(7.24)): exact hand cases on gates, a drifting tube
// with a known loop contracted as in Fig. 7.8, what it reports as changed,
// inconsistency, errors, and the contractor laws on random looped
// trajectories (truth kept, contraction, thread independence).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "sillage/testing/contractor_kit.h"
#include "slam_test_util.h"
#include "sillage/error.h"
#include "sillage/slam/ctc_t1t2.h"
#include "sillage/tube/trajectory.h"

using namespace sillage;

namespace {

// p ∈ [-10, 10] on [0, 10] with w unknown, gates 2 and 7 given.
struct TwoGates {
  std::shared_ptr<TDomain> td = TDomain::create(0.0, 10.0, 1.0);
  Tube p{td, Interval(-10, 10)}, w{td, Interval()};
  TwoGates(Interval g2, Interval g7) {
    p.set_gate(2, g2);
    p.set_gate(7, g7);
  }
};

}  // namespace

TEST(CtcT1T2, KnownTimesIntersectTheTwoGates) {
  // w unknown: only the two gates can learn, each from the other.
  TwoGates c({0, 1}, {0.5, 2});
  Tube &p = c.p, &w = c.w;
  Interval t1(2.0), t2(7.0);
  ASSERT_TRUE(CtcT1T2().contract(t1, t2, p, w));
  EXPECT_EQ(p.gate(2), Interval(0.5, 1));
  EXPECT_EQ(p.gate(7), Interval(0.5, 1));
  EXPECT_EQ(t1, Interval(2.0));
  EXPECT_EQ(t2, Interval(7.0));
  EXPECT_EQ(p.gate(3), Interval(-10, 10));
}

TEST(CtcT1T2, DisjointGatesAreInconsistent) {
  TwoGates c({0, 1}, {2, 3});
  Tube &p = c.p, &w = c.w;
  Interval t1(2.0), t2(7.0);
  EXPECT_FALSE(CtcT1T2().contract(t1, t2, p, w));
  EXPECT_TRUE(t1.is_empty());
  EXPECT_TRUE(t2.is_empty());
  EXPECT_TRUE(p.is_empty());
}

TEST(CtcT1T2, TimesAreContractedWhereTheValuesCannotMeet) {
  // p(t) = t exactly known on [0, 10] (w = 1): p(t1) = p(t2) forces t1 = t2,
  // so [t1] = [1, 4], [t2] = [3, 8] both become [3, 4].
  const auto td = TDomain::create(0.0, 10.0, 0.5);
  Tube p(td, "t"), w(td, Interval(1.0));
  Interval t1(1, 4), t2(3, 8);
  ASSERT_TRUE(CtcT1T2().contract(t1, t2, p, w));
  EXPECT_EQ(t1, Interval(3, 4));
  EXPECT_EQ(t2, Interval(3, 4));
}

// Fig. 7.8: a drifting tube around p*(t) = cos(t) on [0, 2π], the loop
// p*(t1) = p*(2π - t1) with t1 ∈ [1.1, 1.3]; the tube is thin early and
// thick late (dead reckoning), so the loop pulls the late part back.
struct DriftingLoop {
  std::shared_ptr<TDomain> td = TDomain::create(0.0, 2 * std::numbers::pi, 0.01);
  Tube p{td, "cos(t) + [-1,1]*(0.02 + 0.1*t)"};
  Tube w{td, "-sin(t) + [-0.01,0.01]"};
  Trajectory truth{"cos(t)", td->t0_tf()};
};

TEST(CtcT1T2, DriftingTubeIsPulledBackByTheLoop) {
  DriftingLoop c;
  const Tube before = c.p;
  Interval t1(1.1, 1.3), t2(4.9, 5.3);
  ASSERT_TRUE(CtcT1T2().contract(t1, t2, c.p, c.w));
  EXPECT_TRUE(c.p.is_subset(before));
  EXPECT_TRUE(c.p.contains(c.truth));
  const double t1s = 1.2, t2s = 2 * std::numbers::pi - 1.2;
  EXPECT_TRUE(t1.contains(t1s) && t2.contains(t2s));
  EXPECT_TRUE(t1.is_subset(Interval(1.1, 1.3)) && t2.is_subset(Interval(4.9, 5.3)));
  // Around t2 the tube is now about as thin as [p]([t1]) allows: the width at
  // t = 5.1 drops from 2(0.02 + 0.51) = 1.06 to below 0.6.
  const std::size_t k = c.td->slice_index(5.1);
  EXPECT_GT(before.thickness(k), 1.0);
  EXPECT_LT(c.p.thickness(k), 0.6);
  EXPECT_LT(c.p.volume(), before.volume());
}

TEST(CtcT1T2, ReportsExactlyTheAtomsThatChanged) {
  DriftingLoop c;
  const Tube before = c.p;
  Interval t1(1.1, 1.3), t2(4.9, 5.3);
  std::vector<std::size_t> atoms;
  const std::vector<TubeChanges> logs{TubeChanges(atoms, 0, 0.0)};
  ASSERT_TRUE(CtcT1T2().contract(t1, t2, {&c.p}, {&c.w}, logs));
  std::vector<bool> reported(2 * c.p.nb_slices() + 1, false);
  for (std::size_t a : atoms) reported.at(a) = true;
  std::size_t nb_changed = 0;
  for (std::size_t k = 0; k < c.p.nb_slices(); ++k) {
    if (c.p.slice(k) != before.slice(k)) {
      ++nb_changed;
      EXPECT_TRUE(reported[2 * k + 1]) << "slice " << k;
    }
  }
  for (std::size_t k = 0; k <= c.p.nb_slices(); ++k) {
    if (c.p.gate(k) != before.gate(k)) {
      ++nb_changed;
      EXPECT_TRUE(reported[2 * k]) << "gate " << k;
    }
  }
  EXPECT_GT(nb_changed, 0u);
  // Far before [t1] nothing is learned (the backward front from [t1] stops
  // once it holds the gates): the contraction stays local.
  EXPECT_LT(nb_changed, 2 * c.p.nb_slices());
}

TEST(CtcT1T2, VectorCaseUsesOneTimePairForAllComponents) {
  // p*(t) = (cos t, sin t): a full circle, p*(0) = p*(2π) only. With [t1]
  // = [0, 0.5] and [t2] = [5.5, 2π] the second component pins the pair.
  const auto td = TDomain::create(0.0, 2 * std::numbers::pi, 0.01);
  TubeVector p(std::vector<Tube>{Tube(td, "cos(t) + [-0.05,0.05]"), Tube(td, "sin(t) + [-0.05,0.05]")});
  TubeVector w(std::vector<Tube>{Tube(td, "-sin(t) + [-0.001,0.001]"), Tube(td, "cos(t) + [-0.001,0.001]")});
  Interval t1(0, 0.5), t2(5.5, 2 * std::numbers::pi);
  ASSERT_TRUE(CtcT1T2().contract(t1, t2, p, w));
  EXPECT_TRUE(t1.contains(0.0));
  EXPECT_LT(t1.ub(), 0.2);
  EXPECT_GT(t2.lb(), 2 * std::numbers::pi - 0.2);
}

TEST(CtcT1T2, BadInputSaysWhatAndWhere) {
  const auto td = TDomain::create(0.0, 10.0, 1.0);
  TubeVector p(td, 2), w(td, 3);
  Interval t1(1, 2), t2(3, 4);
  EXPECT_THROW(CtcT1T2().contract(t1, t2, p, w), DimensionError);
  TubeVector w2(td, 2);
  Interval far(20, 30);
  try {
    CtcT1T2().contract(far, t2, p, w2);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("CtcT1T2"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("t1"), std::string::npos);
  }
  EXPECT_THROW(CtcT1T2(1.0), Error);
  EXPECT_THROW(CtcT1T2(0.1, 0), Error);
  const auto other = TDomain::create(0.0, 10.0, 0.5);
  Tube ps(td), ws(other);
  EXPECT_THROW(CtcT1T2().contract(t1, t2, ps, ws), DimensionError);
}

// The laws on random looped trajectories g(t) = f(t) + f(2m - t):
// domains t1, t2, p (2-D), w (2-D).
kit::Case t1t2_case(std::mt19937_64& rng) {
  const auto td = kit::random_tdomain(rng, 30);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double t0 = td->t0(), tf = td->tf();
  // m and d multiples of 2^-10 so that m ± d are exact.
  const double m = std::ldexp(std::round(std::ldexp(t0 + (0.3 + 0.4 * u(rng)) * (tf - t0), 10)), -10);
  const double dmax = std::min(m - t0, tf - m);
  const double d = std::ldexp(std::round(std::ldexp((0.1 + 0.8 * u(rng)) * dmax, 10)), -10);
  const slam_test::LoopedSine g1(rng, m), g2(rng, m);
  kit::Case c;
  c.domains = {kit::around(Interval(m - d), rng, 0.4), kit::around(Interval(m + d), rng, 0.4),
               TubeVector({kit::tube_around(td, g1.position(), rng, 0.5, 0.3),
                           kit::tube_around(td, g2.position(), rng, 0.5, 0.3)}),
               TubeVector({kit::tube_around(td, g1.velocity(), rng, 0.3), kit::tube_around(td, g2.velocity(), rng, 0.3)})};
  c.truth = {Interval(m - d), Interval(m + d), std::vector<kit::Trajectory1>{g1.position(), g2.position()},
             std::vector<kit::Trajectory1>{g1.velocity(), g2.velocity()}};
  return c;
}

TEST(CtcT1T2, ContractorLaws) {
  const auto contract = [](kit::Domains& d) {
    CtcT1T2().contract(std::get<Interval>(d[0]), std::get<Interval>(d[1]), std::get<TubeVector>(d[2]),
                       std::get<TubeVector>(d[3]));
  };
  kit::Options o;
  o.cases = 30;
  o.idempotence = kit::Idempotence::ContractionOnly;
  o.outputs = {0, 1, 2};  // t1, t2 and p emptied together
  o.skip_empty = {3};     // an empty w: CtcEval's own law
  EXPECT_TRUE(kit::check_laws(contract, t1t2_case, o));
}
