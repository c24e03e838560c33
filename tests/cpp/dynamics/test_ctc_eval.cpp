// CtcEval (Prop. 5.1): hand cases from the definition (5.6), with and
// without time uncertainty, sampling at a degenerate t, the variant without
// derivative, inconsistency (Lemma 5.1), the vector case, errors, and the
// truth kept on random tubes around a random trajectory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

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
  // Gate 5 (inside [t]): F from slice 4 = 0 + [0, 1][-1, 1], B alike.
  EXPECT_EQ(y.gate(5), Interval(-1, 1));
  // After [t]: F = [-1, 1] + [-1, 1] at t = 6, one more unit per slice.
  EXPECT_EQ(y.gate(6), Interval(-2, 2));
  EXPECT_EQ(y.gate(10), Interval(-6, 6));
  EXPECT_EQ(y.gate(4), Interval(-2, 2));
  EXPECT_EQ(y.gate(0), Interval(-6, 6));
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
  // Without sampling no gate is created: the slice holding t gives its gates
  // 1 + [0, 1][-1, 1].
  UnitProblem q;
  CtcEval c;
  c.enable_time_sampling(false);
  Interval t2(2.5), z2(1.0);
  ASSERT_TRUE(c.contract(t2, z2, q.y, q.w));
  EXPECT_EQ(q.td->nb_slices(), 10u);
  EXPECT_EQ(q.y.gate(3), Interval(0, 2));
  EXPECT_EQ(q.y.gate(2), Interval(0, 2));
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

// The definition (5.6) evaluated on a fine sampling of t1 ∈ [t], at the gates
// after [t]: hull over t1 of ([y](t1) ∩ [z]) + ∫_{t1}^{t_i} [w], ∩ [y](t_i).
Interval reference_gate(const Tube& y, const Tube& w, const Interval& t, const Interval& z, std::size_t i) {
  const TDomain& td = *y.tdomain();
  Interval hull = Interval::empty();
  const int samples = 2000;
  for (int s = 0; s <= samples; ++s) {
    const double t1 = t.lb() + (t.ub() - t.lb()) * s / samples;
    const Interval v = y(t1) & z;
    if (v.is_empty()) continue;
    // ∫_{t1}^{t_i} [w]: the rest of t1's slice, then whole slices.
    std::size_t k = td.slice_index(t1);
    Interval integral = (Interval(td.t(k + 1)) - Interval(t1)) * w.slice(k);
    for (std::size_t j = k + 1; j < i; ++j) integral += td.slice_width(j) * w.slice(j);
    hull |= v + integral;
  }
  return hull & y.gate(i);
}

TEST(CtcEval, MatchesTheDefinitionOnFineSamplingUpToTheSlices) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    auto td = TDomain::create(0.0, 10.0, 1.0);
    Tube y(td, "sin(t) + [-0.8, 0.8]");
    const Tube w(td, "cos(t) + [-0.2, 0.2]");
    CtcDeriv().contract(y, w);  // a tube consistent with its derivative, as in a network
    const double a = 2 + 4 * u(rng), b = a + 0.3 + 1.5 * u(rng);
    const double c = std::sin(a + (b - a) * u(rng));
    Interval t(a, b), z(c - 0.05, c + 0.05);
    const Tube y0 = y;
    CtcEval ctc;
    ctc.enable_time_sampling(false);
    ASSERT_TRUE(ctc.contract(t, z, y, w));
    for (std::size_t i = td->slice_index(b) + 1; i <= td->nb_slices(); ++i) {
      const Interval ref = reference_gate(y0, w, Interval(a, b), Interval(c - 0.05, c + 0.05), i);
      // Never tighter than the definition (the sampled hull is inside the exact one)...
      EXPECT_TRUE(ref.is_subset(y.gate(i))) << trial << " gate " << i << ": " << y.gate(i) << " vs " << ref;
      // ...and no wider than it, up to one slice of [w]: for t1 inside a slice we use [0, δ][w](k).
      const double margin = 1.0 * w.slice(td->slice_index(a)).mag() + 1.0 * w.slice(td->slice_index(b)).mag();
      EXPECT_LE(y.gate(i).diam(), ref.diam() + 2 * margin + 1e-9) << trial << " gate " << i;
    }
  }
}
