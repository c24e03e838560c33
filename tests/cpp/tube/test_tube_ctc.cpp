// Pointwise constraints on tubes (thesis 3.2.3): hand cases, the guarantee on
// random trajectories (never removed, results are subsets), empty tubes and
// dimension errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sillage/ctc/ctc_algebra.h"
#include "sillage/error.h"
#include "sillage/interval/elementary.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_ctc.h"

#include "kit/close_bounds.h"

using namespace sillage;

namespace {

std::shared_ptr<TDomain> td012() { return TDomain::create(std::vector<double>{0.0, 1.0, 2.0}); }

}  // namespace

TEST(TubeCtc, AdditionHandCase) {
  auto td = td012();
  Tube x(td, Interval(0, 1)), y(td, Interval(0, 1)), a(td, Interval(-10, 10));
  a.set(Interval(1.5, 5), 1);  // slice 1, gates 1 and 2
  const CtcFunction c(Function({"x", "y", "a"}, "x + y - a"));
  EXPECT_TRUE(contract(c, {&x, &y, &a}));
  EXPECT_EQ(a.slice(0), Interval(0, 2));
  EXPECT_EQ(a.slice(1), Interval(1.5, 2));
  EXPECT_EQ(x.slice(0), Interval(0, 1));
  EXPECT_EQ(x.slice(1), Interval(0.5, 1));
  EXPECT_EQ(y.slice(1), Interval(0.5, 1));
  // Gate 1 lies in both slices: [0.5, 1] for x, [1.5, 2] for a.
  EXPECT_EQ(x.gate(1), Interval(0.5, 1));
  EXPECT_EQ(a.gate(1), Interval(1.5, 2));
  EXPECT_EQ(x.gate(0), Interval(0, 1));
}

TEST(TubeCtc, SpeedTimesCosHeading) {
  // v = x4 cos(x3) with small tubes, as in dead reckoning (3.18).
  auto td = TDomain::create(0.0, 1.0, 0.25);
  Tube x3(td, "t/10 + [-0.01, 0.01]"), x4(td, "2 + t + [-0.01, 0.01]"), v(td);
  const Tube x3_0 = x3, x4_0 = x4;
  const CtcFunction c(Function({"x3", "x4", "v"}, "x4*cos(x3) - v"));
  EXPECT_TRUE(contract(c, {&x3, &x4, &v}));
  EXPECT_EQ(x3, x3_0);  // nothing to learn from an unbounded v
  EXPECT_EQ(x4, x4_0);
  // The batch's cos rows (trig_batch.h) may differ from cos by a few ulps.
  for (std::size_t k = 0; k < td->nb_slices(); ++k) {
    const Interval expect = x4.slice(k) * cos(x3.slice(k));
    EXPECT_TRUE(test::close_bounds(v.slice(k), expect, 1e-14)) << k << ": " << v.slice(k) << " vs " << expect;
    const Interval gate = x4.gate(k) * cos(x3.gate(k));
    EXPECT_TRUE(test::close_bounds(v.gate(k), gate, 1e-14)) << k << ": " << v.gate(k) << " vs " << gate;
  }
  // Backward: bounding v bounds x4 (cos(x3) is about 1).
  Tube v2(td, Interval(2.0, 2.2));
  Tube x4b(td, Interval(0, 10));
  EXPECT_TRUE(contract(c, {&x3, &x4b, &v2}));
  EXPECT_TRUE(x4b.codomain().is_subset(Interval(1.9, 2.3)));
  EXPECT_GT(x4b.codomain().lb(), 1.99);
}

TEST(TubeCtc, TubeVectorAndClass) {
  auto td = td012();
  TubeVector x(td, 2, Interval(-5, 5));
  const CtcTubeFunction c(Function({"x", "y"}, "(x - y, x)"), IntervalVector{Interval(0), Interval(1, 2)});
  EXPECT_TRUE(c.contract(x));
  EXPECT_EQ(x[0].codomain(), Interval(1, 2));
  EXPECT_EQ(x[1].codomain(), Interval(1, 2));
}

TEST(TubeCtc, AnyBoxContractor) {
  // x - y = 0 then x + y = 2 (a composition, virtual calls), and a CtcFunction
  // seen as a Ctc (the HC4 path).
  auto td = td012();
  Tube x(td, Interval(0, 3)), y(td, Interval(1, 1.5));
  const CtcCompo c({std::make_shared<CtcFunction>(Function({"x", "y"}, "x - y")),
                    std::make_shared<CtcFunction>(Function({"x", "y"}, "x + y - 2"))});
  EXPECT_TRUE(contract(c, {&x, &y}));
  EXPECT_TRUE(x.codomain().is_subset(Interval(1, 1.5)));
  EXPECT_EQ(y.codomain(), Interval(1));
  TubeVector v(td, 2, Interval(0, 3));
  const Ctc& f = CtcFunction(Function({"x", "y"}, "x - 2*y"));
  EXPECT_TRUE(contract(f, v));
  EXPECT_EQ(v[1].codomain(), Interval(0, 1.5));
  Tube z(td, Interval(5, 6));
  EXPECT_FALSE(contract(c, {&x, &z}));
  EXPECT_TRUE(x.is_empty());
  // An empty slice on input, with a contractor that would "fill" it if called: no trajectory.
  class Fill : public Ctc {
   public:
    Fill() : Ctc(2) {}
    void contract(IntervalVector& b) const override { b = IntervalVector(2, Interval(0, 1)); }
  };
  Tube p(td, Interval(0, 1)), q(td, Interval(0, 1));
  q.set(Interval::empty(), 1);
  EXPECT_FALSE(contract(Fill(), {&p, &q}));
  EXPECT_TRUE(p.slice(0).is_empty() && q.gate(0).is_empty());
}

TEST(TubeCtc, VersionOnlyWhenChanged) {
  auto td = td012();
  Tube x(td, Interval(0, 1)), y(td, Interval(-1, 3));
  const CtcFunction c(Function({"x", "y"}, "x - y"));
  const auto vx = x.version(), vy = y.version();
  contract(c, {&x, &y});
  EXPECT_EQ(x.version(), vx);
  EXPECT_GT(y.version(), vy);
  EXPECT_EQ(y.codomain(), Interval(0, 1));
}

TEST(TubeCtc, Empty) {
  auto td = td012();
  const CtcFunction c(Function({"x", "y"}, "x - y"));
  Tube x(td, Interval(0, 1)), y(td, Interval(0, 1));
  y.set(Interval(2, 3), 1);  // inconsistent on slice 1 only
  EXPECT_FALSE(contract(c, {&x, &y}));
  EXPECT_TRUE(x.is_empty());
  EXPECT_TRUE(y.is_empty());
  for (const Interval& s : x.slices()) EXPECT_TRUE(s.is_empty());
  for (const Interval& g : y.gates()) EXPECT_TRUE(g.is_empty());

  Tube a(td, Interval(0, 1)), b(td, Interval(0, 1));
  b.set_gate(2, Interval::empty());  // an empty input: no trajectory
  EXPECT_FALSE(contract(c, {&a, &b}));
  EXPECT_TRUE(a.slice(0).is_empty());
}

TEST(TubeCtc, Errors) {
  auto td = td012();
  const CtcFunction c(Function({"x", "y"}, "x - y"));
  Tube x(td, Interval(0, 1)), y(td, Interval(0, 1)), z(TDomain::create(0.0, 2.0, 1.0), Interval(0, 1));
  EXPECT_THROW(contract(c, {&x}), DimensionError);
  EXPECT_THROW(contract(c, {&x, &y, &y}), DimensionError);
  EXPECT_THROW(contract(c, {&x, &z}), DimensionError);  // another TDomain, even if equal times
  EXPECT_THROW(contract(c, {&x, nullptr}), Error);
  EXPECT_THROW(contract(c, {&x, &x}), Error);
  TubeVector v(td, 3);
  EXPECT_THROW(contract(c, v), DimensionError);
}

// Random values on a dyadic grid, so that x3 = x1 * x2 - x1 is exact in double
// arithmetic: the points are exact solutions of the constraint.
TEST(TubeCtc, PropertyNeverRemovesASolution) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> val(-256, 256), marg(0, 64), nslices(1, 20);
  const CtcFunction c(Function({"x1", "x2", "x3"}, "x1*x2 - x1 - x3"));
  const int inner = 3;
  int contracted = 0;  // trials where something was removed: the test is not vacuous
  for (int trial = 0; trial < 200; ++trial) {
    const int N = nslices(rng);
    auto td = TDomain::create(0.0, 1.0, 1.0 / N);
    const std::size_t n = td->nb_slices();
    // points[j][k]: variable j at gate k (k <= n) / at inner time i of slice s.
    std::vector<std::vector<double>> gate(3, std::vector<double>(n + 1));
    std::vector<std::vector<std::vector<double>>> in(3, std::vector<std::vector<double>>(n));
    auto draw = [&](double& a, double& b, double& r) {
      a = val(rng) / 64.0, b = val(rng) / 64.0, r = a * b - a;
    };
    for (std::size_t k = 0; k <= n; ++k) draw(gate[0][k], gate[1][k], gate[2][k]);
    for (std::size_t k = 0; k < n; ++k) {
      for (int i = 0; i < inner; ++i) {
        double a, b, r;
        draw(a, b, r);
        in[0][k].push_back(a), in[1][k].push_back(b), in[2][k].push_back(r);
      }
    }
    std::vector<Tube> tubes;
    for (int j = 0; j < 3; ++j) {
      std::vector<Interval> s(n), g(n + 1);
      for (std::size_t k = 0; k <= n; ++k) g[k] = Interval(gate[j][k]).inflate(marg(rng) / 64.0);
      for (std::size_t k = 0; k < n; ++k) {
        Interval h = Interval(gate[j][k]) | Interval(gate[j][k + 1]);
        for (double p : in[j][k]) h |= Interval(p);
        s[k] = h.inflate(marg(rng) / 64.0);
        g[k] &= s[k], g[k + 1] &= s[k];
      }
      tubes.emplace_back(td, s, g);
    }
    const std::vector<Tube> before = tubes;
    ASSERT_TRUE(contract(c, {&tubes[0], &tubes[1], &tubes[2]}));
    for (int j = 0; j < 3; ++j) {
      if (tubes[j] != before[j]) ++contracted;
      EXPECT_TRUE(tubes[j].is_subset(before[j]));
      for (std::size_t k = 0; k <= n; ++k) ASSERT_TRUE(tubes[j].gate(k).contains(gate[j][k])) << trial;
      for (std::size_t k = 0; k < n; ++k)
        for (double p : in[j][k]) ASSERT_TRUE(tubes[j].slice(k).contains(p)) << trial;
    }
    // A second pass may only contract further.
    std::vector<Tube> again = tubes;
    contract(c, {&again[0], &again[1], &again[2]});
    for (int j = 0; j < 3; ++j) EXPECT_TRUE(again[j].is_subset(tubes[j]));
  }
  EXPECT_GT(contracted, 100);
}

// A continuous case: x2 = sin(x1) with x1 = t; the true sin(t) at sampled
// times stays in the contracted tube.
TEST(TubeCtc, PropertyContinuous) {
  auto td = TDomain::create(0.0, 10.0, 0.1);
  Tube x1(td, "t"), x2(td, Interval(-3, 3));
  const CtcFunction c(Function({"a", "b"}, "sin(a) - b"));
  contract(c, {&x1, &x2});
  EXPECT_LT(x2.max_thickness(), 0.11);
  for (std::size_t k = 0; k < td->nb_slices(); ++k) {
    for (int i = 0; i <= 10; ++i) {
      const double t = td->t(k) + i * (td->t(k + 1) - td->t(k)) / 10;
      if (t > td->t(k + 1)) continue;
      EXPECT_TRUE(sin(Interval(t)).is_subset(x2.slice(k))) << t;
    }
    EXPECT_TRUE(sin(Interval(td->t(k))).is_subset(x2.gate(k)));
  }
}
