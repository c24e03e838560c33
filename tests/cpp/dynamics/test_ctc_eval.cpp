// CtcEval (Prop. 5.1): hand cases from the definition (5.6), with and
// without time uncertainty, sampling at a degenerate t, the variant without
// derivative, inconsistency (Lemma 5.1), the vector case, errors, and the
// truth kept on random tubes around a random trajectory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/deriv_test_util.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/error.h"
#include "sillage/tube/trajectory.h"

using namespace sillage;

namespace {

// y ∈ [-10, 10] with y' ∈ [-1, 1] on [0, 10], slices of 1.
struct UnitProblem {
  std::shared_ptr<TDomain> td = TDomain::create(0.0, 10.0, 1.0);
  Tube y{td, Interval(-10, 10)};
  Tube w{td, Interval(-1, 1)};
};

}  // namespace

TEST(CtcEval, KnownTimeAndValueShapeTheGatesAround) {
  UnitProblem p;
  Tube& y = p.y;
  const Tube& w = p.w;
  Interval t(5.0), z(0.0);
  ASSERT_TRUE(CtcEval().contract(t, z, y, w));
  EXPECT_EQ(t, Interval(5.0));
  EXPECT_EQ(z, Interval(0.0));
  for (int k = 0; k <= 10; ++k) {
    const double r = std::abs(k - 5);
    EXPECT_EQ(y.gate(k), Interval(-r, r)) << k;
  }
  // Slice 5: the polygon between gates [0] and [-1, 1] with slopes [-1, 1].
  EXPECT_EQ(y.slice(5), Interval(-1, 1));
}

TEST(CtcEval, UncertainTimeUsesBothFronts) {
  UnitProblem p;
  Tube& y = p.y;
  const Tube& w = p.w;
  Interval t(4.5, 5.5), z(0.0);
  ASSERT_TRUE(CtcEval().contract(t, z, y, w));
  EXPECT_EQ(t, Interval(4.5, 5.5));
  // Gate 5 (inside [t]): y(t1) = 0 for some t1 ∈ [4.5, 5.5], so
  // y(5) ∈ 0 + [0, 0.5][-1, 1] (only the half of slice 4 inside [t] counts).
  EXPECT_EQ(y.gate(5), Interval(-0.5, 0.5));
  // After [t]: t1 >= 4.5, one more unit per slice.
  EXPECT_EQ(y.gate(6), Interval(-1.5, 1.5));
  EXPECT_EQ(y.gate(10), Interval(-5.5, 5.5));
  EXPECT_EQ(y.gate(4), Interval(-1.5, 1.5));
  EXPECT_EQ(y.gate(0), Interval(-5.5, 5.5));
}

TEST(CtcEval, TimeAndValueAreContractedThroughTheTube) {
  auto td = TDomain::create(0.0, 10.0, 0.5);
  Tube y(td, "t");
  const Tube w(td, Interval(1.0));
  Interval t(0.0, 10.0), z(3.0, 3.25);
  ASSERT_TRUE(CtcEval().contract(t, z, y, w));
  // y(t) = t: t* ∈ [3, 3.25]; with the derivative the polygon is the line.
  EXPECT_TRUE(t.is_superset(Interval(3.0, 3.25)));
  EXPECT_TRUE(t.is_subset(Interval(2.999999, 3.250001))) << t;
  Interval t2(3.0, 3.5), z2(0.0, 100.0);
  ASSERT_TRUE(CtcEval().contract(t2, z2, y, w));
  EXPECT_TRUE(z2.is_subset(Interval(2.999999, 3.500001))) << z2;
}

TEST(CtcEval, DegenerateTimeSamplesTheDomain) {
  UnitProblem p;
  Interval t(2.5), z(1.0);
  ASSERT_TRUE(CtcEval().contract(t, z, p.y, p.w));
  EXPECT_EQ(p.td->nb_slices(), 11u);
  EXPECT_EQ(p.y(2.5), Interval(1.0));
  EXPECT_EQ(p.y.gate(4), Interval(0.5, 1.5));  // t = 3: 1 + 0.5 [-1, 1]
  // Without sampling no gate is created: from t = 2.5 inside slice 2, its
  // gates are 1 + 0.5 [-1, 1] (the polygon, not the whole slice).
  UnitProblem q;
  CtcEval c;
  c.enable_time_sampling(false);
  Interval t2(2.5), z2(1.0);
  ASSERT_TRUE(c.contract(t2, z2, q.y, q.w));
  EXPECT_EQ(q.td->nb_slices(), 10u);
  EXPECT_EQ(q.y.gate(3), Interval(0.5, 1.5));
  EXPECT_EQ(q.y.gate(2), Interval(0.5, 1.5));
  EXPECT_EQ(q.y.eval(Interval(2.5), q.w), Interval(0, 2));  // without a gate at 2.5, its gates' polygon
}

TEST(CtcEval, WithoutDerivative) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  Tube y(td, std::vector<Interval>{{0, 1}, {1, 2}, {2, 3}, {3, 4}});
  Interval t(0.0, 4.0), z(2.5, 2.6);
  ASSERT_TRUE(CtcEval().contract(t, z, y));
  EXPECT_EQ(t, Interval(2.0, 3.0));  // only slice 2 meets z
  Interval t2(2.0), z2(0.0, 10.0);
  ASSERT_TRUE(CtcEval().contract(t2, z2, y));
  EXPECT_EQ(z2, Interval(2.0));  // gate 2 = [1, 2] ∩ [2, 3]
}

TEST(CtcEval, InconsistencyEmptiesEverything) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  Tube y(td, Interval(5, 6));
  const Tube w(td, Interval(-1, 1));
  Interval t(1.0, 2.0), z(0.0);
  EXPECT_FALSE(CtcEval().contract(t, z, y, w));
  EXPECT_TRUE(t.is_empty());
  EXPECT_TRUE(z.is_empty());
  EXPECT_TRUE(y.slice(0).is_empty() && y.gate(4).is_empty());
}

TEST(CtcEval, VectorCaseSharesTheTime) {
  auto td = TDomain::create(0.0, 10.0, 0.5);
  TubeVector y(td, "(t, 2*t)");
  const TubeVector w(td, IntervalVector{{1.0}, {2.0}});
  Interval t(0.0, 10.0);
  IntervalVector z{{0.0, 10.0}, {4.0, 5.0}};  // y2 = 2t: t ∈ [2, 2.5], so y1 ∈ [2, 2.5]
  ASSERT_TRUE(CtcEval().contract(t, z, y, w));
  EXPECT_TRUE(t.is_subset(Interval(1.999999, 2.500001))) << t;
  EXPECT_TRUE(z[0].is_subset(Interval(1.999999, 2.500001))) << z[0];
}

TEST(CtcEval, Errors) {
  auto td = TDomain::create(0.0, 4.0, 1.0), other = TDomain::create(0.0, 4.0, 2.0);
  Tube y(td);
  Interval t(5.0, 6.0), z(0.0);
  EXPECT_THROW(CtcEval().contract(t, z, y, Tube(td)), Error);  // t outside the domain
  Interval t2(1.0);
  EXPECT_THROW(CtcEval().contract(t2, z, y, Tube(other)), DimensionError);
  TubeVector yv(td, 2), wv(td, 3);
  IntervalVector zv(2);
  EXPECT_THROW(CtcEval().contract(t2, zv, yv, wv), DimensionError);
}

TEST(CtcEval, TruthIsNeverRemoved) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  int contracted = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const double a = 1 + u(rng), b = 0.5 + u(rng), c = u(rng) * 6;
    const std::string f = std::to_string(a) + "*sin(" + std::to_string(b) + "*t + " + std::to_string(c) + ")";
    const std::string df = std::to_string(a * b) + "*cos(" + std::to_string(b) + "*t + " + std::to_string(c) + ")";
    auto td = TDomain::create(0.0, 10.0, 0.1 + 0.2 * u(rng));
    const double e = 0.05 + u(rng);
    Tube y(td, f + " + [-" + std::to_string(e) + ", " + std::to_string(e) + "]");
    const Tube w(td, df + " + [-0.05, 0.05]");
    const double ts = 10 * u(rng);
    const double vs = a * std::sin(b * ts + c);
    Interval t(std::max(0.0, ts - u(rng)), std::min(10.0, ts + u(rng)));
    Interval z(vs - 0.01 * u(rng) - 1e-9, vs + 0.01 * u(rng) + 1e-9);
    const double volume_before = y.volume();
    ASSERT_TRUE(CtcEval().contract(t, z, y, w)) << trial;
    EXPECT_TRUE(t.contains(ts)) << trial;
    EXPECT_TRUE(z.contains(vs)) << trial;
    EXPECT_TRUE(y.contains(Trajectory(f, td->t0_tf()))) << trial;
    EXPECT_LE(y.volume(), volume_before) << trial;
    contracted += y.volume() < volume_before;
  }
  EXPECT_GE(contracted, 20);  // a thin tube and a wide [t] may teach nothing
}

TEST(CtcEval, NetworkFormLogsExactlyTheAtomsThatShrank) {
  UnitProblem p;
  const Tube before = p.y;
  Interval t(4.5, 5.5);
  IntervalVector z{Interval(0.0)};
  std::vector<std::vector<std::size_t>> changed;
  ASSERT_TRUE(CtcEval().contract(t, z, {&p.y}, {&p.w}, 0.0, changed));
  ASSERT_EQ(changed.size(), 1u);
  std::vector<std::size_t> expected;
  for (std::size_t k = 0; k <= p.y.nb_slices(); ++k) {
    if (p.y.gate(k) != before.gate(k)) expected.push_back(2 * k);
    if (k < p.y.nb_slices() && p.y.slice(k) != before.slice(k)) expected.push_back(2 * k + 1);
  }
  std::vector<std::size_t> got = changed[0];
  std::sort(got.begin(), got.end());
  got.erase(std::unique(got.begin(), got.end()), got.end());
  EXPECT_EQ(got, expected);
  EXPECT_FALSE(expected.empty());
  // The TubeChanges form reports the same atoms.
  UnitProblem q;
  Interval t2(4.5, 5.5);
  IntervalVector z2{Interval(0.0)};
  std::vector<std::size_t> logged;
  ASSERT_TRUE(CtcEval().contract(t2, z2, {&q.y}, {&q.w}, {TubeChanges(logged, 0, 0.0)}));
  std::sort(logged.begin(), logged.end());
  logged.erase(std::unique(logged.begin(), logged.end()), logged.end());
  EXPECT_EQ(logged, expected);
}

// The definition (5.6) on a fine sampling of t1 ∈ [t] that holds the bounds
// of [t] and every time point inside it, at gate i:
//   hull over t1 of ([y](t1) ∩ [z]) + ∫_{t1}^{t_i} [w]   (backward if t1 > t_i),
// with [y](t1) the value of the tube at t1 (its slice, or its gate).
// Between two such samples the integral is affine in t1 and [y](t1) is
// constant, so the sampled hull is the exact one (up to rounding).
Interval definition_at_gate(const Tube& y, const Tube& w, const Interval& t, const Interval& z, std::size_t i) {
  const TDomain& td = *y.tdomain();
  std::vector<double> t1s{t.lb(), t.ub()};
  for (std::size_t k = 0; k <= td.nb_slices(); ++k) {
    if (t.contains(td.t(k))) t1s.push_back(td.t(k));
  }
  for (int s = 1; s < 50; ++s) t1s.push_back(t.lb() + (t.ub() - t.lb()) * s / 50);
  Interval hull = Interval::empty();
  const double ti = td.t(i);
  for (const double t1 : t1s) {
    const Interval v = y(t1) & z;
    if (v.is_empty()) continue;
    Interval integral(0.0);
    const double a = std::min(t1, ti), b = std::max(t1, ti);
    for (std::size_t k = 0; k < td.nb_slices(); ++k) {
      const double lo = std::max(a, td.t(k)), hi = std::min(b, td.t(k + 1));
      if (lo < hi) integral += (Interval(hi) - Interval(lo)) * w.slice(k);
    }
    hull |= t1 <= ti ? v + integral : v - integral;
  }
  return hull & y.gate(i);
}

// A random slicing of [0, 10] (slices of 0.3 to 1.5) and random bounds of
// [t] anywhere in it.
// The issue's case: slices of 2 over [-1, 7], [w] = -1, [-1, 1], -1, [-1, 1],
// nothing known of y, one value z ∈ [-1, 1] at t ∈ [0, 6]. The exact set of
// (5.6): y(0) ∈ [-2, 7], y(1) ∈ [-3, 6], y(3) ∈ [-4, 4], y(5) ∈ [-6, 2],
// y(6) ∈ [-7, 2] (and y(-1) ∈ [-1, 8], y(7) ∈ [-8, 3]).
struct IssueCase {
  std::shared_ptr<TDomain> td = TDomain::create(std::vector<double>{-1, 1, 3, 5, 7});
  Tube y{td};
  Tube w{td, std::vector<Interval>{Interval(-1), Interval(-1, 1), Interval(-1), Interval(-1, 1)}};
  Interval t{0.0, 6.0}, z{-1.0, 1.0};
};

TEST(CtcEval, TimeInsideSlicesGivesTheExactSetOfTheDefinition) {
  IssueCase c;
  CtcEval ctc;
  ctc.enable_time_sampling(false);
  ASSERT_TRUE(ctc.contract(c.t, c.z, c.y, c.w));
  EXPECT_EQ(c.td->nb_slices(), 4u);
  EXPECT_EQ(c.y.gate(0), Interval(-1, 8));
  EXPECT_EQ(c.y.gate(1), Interval(-3, 6));
  EXPECT_EQ(c.y.gate(2), Interval(-4, 4));
  EXPECT_EQ(c.y.gate(3), Interval(-6, 2));
  EXPECT_EQ(c.y.gate(4), Interval(-8, 3));
  // Inside slice 0 ([w] = -1) the polygon gives y(0) exactly; inside slice 3
  // ([w] = [-1, 1]) a gate at 6 is needed to hold [-7, 2].
  EXPECT_EQ(c.y.eval(Interval(0.0), c.w), Interval(-2, 7));
  EXPECT_EQ(c.y.eval(Interval(6.0), c.w), Interval(-7, 3));
}

TEST(CtcEval, TimeBoundsAsGatesGiveTheExactSetEverywhere) {
  IssueCase c;
  c.td->sample(0.0);
  c.td->sample(6.0);
  ASSERT_TRUE(CtcEval().contract(c.t, c.z, c.y, c.w));
  const std::vector<std::pair<double, Interval>> expected{
      {-1, {-1, 8}}, {0, {-2, 7}}, {1, {-3, 6}}, {3, {-4, 4}}, {5, {-6, 2}}, {6, {-7, 2}}, {7, {-8, 3}}};
  for (const auto& [ti, x] : expected) EXPECT_EQ(c.y.gate(c.td->time_index(ti)), x) << "t = " << ti;
}

TEST(CtcEval, UnknownTubeMatchesTheDefinitionExactlyWithTimeBoundsAnywhere) {
  // Nothing known of y: (5.6) is z + ∫[w] from every t1 ∈ [t], with no
  // other constraint, so every gate must equal the sampled definition.
  std::mt19937 rng(14);
  for (int trial = 0; trial < 60; ++trial) {
    const auto c = test::random_unknown_eval_case(rng);
    const auto& td = c.td;
    const Tube& w = c.w;
    Tube y(td);
    const Interval t0 = c.t, z0 = c.z;
    Interval t = t0, z = z0;
    CtcEval ctc;
    ctc.enable_time_sampling(false);
    ASSERT_TRUE(ctc.contract(t, z, y, w)) << trial;
    for (std::size_t i = 0; i <= td->nb_slices(); ++i) {
      const Interval ref = definition_at_gate(Tube(td), w, t0, z0, i);
      const Interval got = y.gate(i);
      EXPECT_TRUE(ref.is_subset(got + Interval(-1e-9, 1e-9))) << trial << " gate " << i << ": " << got << " vs " << ref;
      EXPECT_TRUE(got.is_subset(ref + Interval(-1e-9, 1e-9))) << trial << " gate " << i << ": " << got << " vs " << ref;
    }
  }
}

TEST(CtcEval, NeverLooserThanTheDefinitionAndKeepsTheTruth) {
  // Tubes around a true trajectory, consistent with their derivative (as in
  // a network), [t] anywhere: the gates are inside (5.6) (tighter where the
  // polygon of a slice knows more than its box), the truth is kept, and
  // [t] rounded out to whole slices gives a result at least as wide.
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(0, 1);
  int tighter = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const auto td = test::random_tdomain(rng);
    const double a = 1 + u(rng), b = 0.5 + u(rng), c = 6 * u(rng);
    const auto f = [&](double t) { return a * std::sin(b * t + c); };
    const std::string fs = std::to_string(a) + "*sin(" + std::to_string(b) + "*t+" + std::to_string(c) + ")";
    const std::string dfs = std::to_string(a * b) + "*cos(" + std::to_string(b) + "*t+" + std::to_string(c) + ")";
    Tube y(td, fs + "+[-0.7,0.7]");
    const Tube w(td, dfs + "+[-0.1,0.1]");
    CtcDeriv().contract(y, w);
    const double ts = 10 * u(rng);
    const Interval t0 = Interval(std::max(0.0, ts - 2 * u(rng)), std::min(10.0, ts + 2 * u(rng)));
    const Interval z0(f(ts) - 0.05 * u(rng) - 1e-6, f(ts) + 0.05 * u(rng) + 1e-6);
    CtcEval ctc;
    ctc.enable_time_sampling(false);
    Tube y1 = y;
    Interval t = t0, z = z0;
    ASSERT_TRUE(ctc.contract(t, z, y1, w)) << trial;
    EXPECT_TRUE(t.contains(ts) && z.contains(f(ts))) << trial;
    EXPECT_TRUE(y1.contains(Trajectory(fs, td->t0_tf()))) << trial;
    std::size_t first = 0, last = 0;
    slice_range(*td, t0, first, last, "test");
    Tube y2 = y;
    Interval t2(td->t(first), td->t(last + 1)), z2 = z0;
    ASSERT_TRUE(ctc.contract(t2, z2, y2, w)) << trial;
    bool strictly = false;
    for (std::size_t i = 0; i <= td->nb_slices(); ++i) {
      const Interval ref = definition_at_gate(y, w, t0, z0, i);
      EXPECT_TRUE(y1.gate(i).is_subset(ref + Interval(-1e-9, 1e-9))) << trial << " gate " << i << ": " << y1.gate(i)
                                                                     << " vs " << ref;
      EXPECT_TRUE(y1.gate(i).is_subset(y2.gate(i))) << trial << " gate " << i;
      strictly = strictly || y1.gate(i).diam() < y2.gate(i).diam() - 1e-6;
    }
    tighter += strictly;
  }
  EXPECT_GE(tighter, 10);  // rounding [t] out to slices loses something
}

TEST(CtcEval, OneCallIsAFixedPoint) {
  // A network does not wake a contractor on its own changes: a second call
  // must change nothing, bit for bit.
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 30; ++trial) {
    const auto td = test::random_tdomain(rng);
    Tube y(td, "sin(t)+[-0.6,0.6]");
    const Tube w(td, "cos(t)+[-0.2,0.2]");
    const double ts = 10 * u(rng);
    Interval t(std::max(0.0, ts - u(rng)), std::min(10.0, ts + u(rng)));
    Interval z(std::sin(ts) - 0.1 * u(rng) - 1e-6, std::sin(ts) + 0.1 * u(rng) + 1e-6);
    CtcEval ctc;
    ctc.enable_time_sampling(false);
    ASSERT_TRUE(ctc.contract(t, z, y, w));
    const Tube y1 = y;
    const Interval t1 = t, z1 = z;
    ASSERT_TRUE(ctc.contract(t, z, y, w));
    EXPECT_TRUE(t == t1 && z == z1) << trial;
    for (std::size_t k = 0; k < td->nb_slices(); ++k) {
      EXPECT_EQ(y.slice(k), y1.slice(k)) << trial << " slice " << k;
      EXPECT_EQ(y.gate(k + 1), y1.gate(k + 1)) << trial << " gate " << k + 1;
    }
  }
}

// y' ∈ [0, 1], y = 0 at some t ∈ [3.5, 4.5], slices of 1, in a network. The
// exact set (5.6) at 3.75 is [-0.75, 0.25] (t1 <= 3.75: [0, 0.25]; t1 >=
// 3.75: [-0.75, 0]). With the bounds of [t] as gates the network holds it;
// without them the gates 3 and 4 only give [-0.75, 0.5] there.
Interval network_value_at_3_75(bool gates_at_time_bounds) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  auto t = std::make_shared<Interval>(3.5, 4.5);
  if (gates_at_time_bounds) td->sample(*t);
  auto y = std::make_shared<Tube>(td);
  auto w = std::make_shared<Tube>(td, Interval(0, 1));
  auto z = std::make_shared<Interval>(0.0);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {y, w});
  cn.add(std::make_shared<CtcEval>(), {t, z, y, w});
  EXPECT_FALSE(cn.contract().empty);
  return y->eval(Interval(3.75), *w);
}

TEST(CtcEval, TimeBoundsAsGatesMakeLaterQueriesInsideTight) {
  EXPECT_EQ(network_value_at_3_75(true), Interval(-0.75, 0.25));
  EXPECT_EQ(network_value_at_3_75(false), Interval(-0.75, 0.5));
}

TEST(CtcEval, TDomainSampledAtBothBoundsOfAnInterval) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  Tube y(td, Interval(-1, 1));
  td->sample(Interval(3.5, 4.5));
  EXPECT_EQ(td->nb_slices(), 12u);
  EXPECT_TRUE(td->is_time_point(3.5) && td->is_time_point(4.5));
  td->sample(Interval(-5.0, 4.0));  // -5 is outside, 4 already a time point
  td->sample(Interval::empty());
  EXPECT_EQ(td->nb_slices(), 12u);
  EXPECT_EQ(y.nb_slices(), 12u);
  EXPECT_THROW(td->sample(Interval(20.0, 30.0)), Error);
}

// The same network, the bounds of [t] added as gates by the network itself
// (after CtcDeriv was bound to the tube): the nodes are rebuilt on the new
// slices before the propagation.
TEST(CtcEval, NetworkAddsTheTimeBoundsAsGates) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  auto y = std::make_shared<Tube>(td);
  auto w = std::make_shared<Tube>(td, Interval(0, 1));
  auto t = std::make_shared<Interval>(3.5, 4.5), z = std::make_shared<Interval>(0.0);
  auto t2 = std::make_shared<Interval>(7.25, 8.0), z2 = std::make_shared<Interval>(1.0);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {y, w});
  auto eval = std::make_shared<CtcEval>();
  eval->enable_gates_at_time_bounds(true);
  cn.add(eval, {t, z, y, w});
  cn.add(eval, {t2, z2, y, w});
  EXPECT_EQ(td->nb_slices(), 10u);  // not before contract()
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ(td->nb_slices(), 13u);  // 3.5, 4.5, 7.25 (8 is one already)
  EXPECT_EQ(y->eval(Interval(3.75), *w), Interval(-0.75, 0.25));
  EXPECT_EQ(y->gate(td->time_index(7.25)), Interval(0.25, 1.0));  // y(8) = 1 at worst, y' <= 1 back from 8
  EXPECT_EQ(y->gate(td->time_index(4.5)), Interval(0, 1));
  // A second contract changes nothing and adds no gate.
  const Tube before = *y;
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ(td->nb_slices(), 13u);
  for (std::size_t k = 0; k < td->nb_slices(); ++k) {
    EXPECT_EQ(y->gate(k), before.gate(k)) << k;
    EXPECT_EQ(y->slice(k), before.slice(k)) << k;
  }
}
